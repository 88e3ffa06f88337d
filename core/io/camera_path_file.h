#pragma once
// Camera path files: one pose a line,
//   x y z yaw pitch [seconds]     (metres, degrees; '#' starts a comment)
// where seconds, given on every line or on none, is when the pose is
// passed (a walk recorded in the viewer); without it, one pose a frame.

#include "core/geometry/camera_path.h"

#include <filesystem>

namespace triwalk {

// Throws InputError naming the file and line.
CameraPath readCameraPath(const std::filesystem::path& path);
// Atomic: the file is whole or unchanged.
void writeCameraPath(const std::filesystem::path& path, const CameraPath& cameraPath);

}  // namespace triwalk
