#include "app/bench/temporary_capture.h"

namespace triwalk {

TemporaryCapture::TemporaryCapture(const Scene& scene, const CaptureOptions& options, const std::string& name)
    : directory_(std::filesystem::temp_directory_path() / name) {
  std::filesystem::remove_all(directory_);
  summary_ = captureDataset(scene, "builtin", options, directory_);
}

TemporaryCapture::~TemporaryCapture() {
  std::error_code ignored;
  std::filesystem::remove_all(directory_, ignored);
}

}  // namespace triwalk
