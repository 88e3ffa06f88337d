#pragma once
// The viewer's "export video": the walk's frames at render's frame rate,
// one frame a pass of the viewer's loop (the window stays live and Esc
// cancels), encoded as `render --path FILE --video` would. Cancelled or
// failed, it leaves no file (app/video/video_file.h).

#include "app/video/video_file.h"
#include "core/geometry/camera_path.h"

#include <filesystem>
#include <vector>

namespace triwalk {

class PathVideoExport {
public:
  // Throws InputError before any frame: a file FFmpeg cannot write, an odd
  // size, a walk of more than an hour.
  PathVideoExport(const CameraPath& path, const std::filesystem::path& file, int width, int height, int framesPerSecond);

  bool done() const { return next_ >= poses_.size(); }
  const CameraPose& nextPose() const { return poses_[next_]; }
  // The next pose's frame; after the last, the video is finished and moved into place.
  void write(const Rgb8Image& frame);

  size_t framesWritten() const { return next_; }
  size_t frames() const { return poses_.size(); }
  int width() const { return width_; }
  int height() const { return height_; }

private:
  std::vector<CameraPose> poses_;
  int width_, height_;
  VideoWriter video_;
  size_t next_ = 0;
};

}  // namespace triwalk
