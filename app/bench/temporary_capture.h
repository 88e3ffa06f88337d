#pragma once
// A data set the bench captures into the temporary folder and removes when
// it is done with it, also when it stops on an error or Ctrl-C.

#include "render/capture/dataset_capture.h"

#include <filesystem>
#include <string>

namespace triwalk {

class TemporaryCapture {
public:
  // name: the folder's name in the temporary folder; one left by a run
  // that was stopped is replaced.
  TemporaryCapture(const Scene& scene, const CaptureOptions& options, const std::string& name);
  ~TemporaryCapture();
  TemporaryCapture(const TemporaryCapture&) = delete;
  TemporaryCapture& operator=(const TemporaryCapture&) = delete;

  const std::filesystem::path& directory() const { return directory_; }
  const CaptureSummary& summary() const { return summary_; }

private:
  std::filesystem::path directory_;
  CaptureSummary summary_;
};

}  // namespace triwalk
