#include "app/viewer/path_video_export.h"

#include "core/support/errors.h"

#include <string>

namespace triwalk {

namespace {

std::vector<CameraPose> checkedFramePoses(const CameraPath& path, const std::filesystem::path& file, int framesPerSecond) {
  if (frameCount(path, framesPerSecond) > kMaxPathFrames) {
    throw InputError(file.string(), "the walk lasts more than " + std::to_string(kMaxPathFrames) + " frames");
  }
  return framePoses(path, framesPerSecond);
}

}  // namespace

PathVideoExport::PathVideoExport(const CameraPath& path, const std::filesystem::path& file, int width, int height,
                                 int framesPerSecond)
    : poses_(checkedFramePoses(path, file, framesPerSecond)), width_(width), height_(height),
      video_(file, width, height, framesPerSecond) {}

void PathVideoExport::write(const Rgb8Image& frame) {
  video_.write(frame);
  if (++next_ == poses_.size()) video_.commit();
}

}  // namespace triwalk
