// Fuzzes readCameraPath and the playback of what it reads: any bytes as a camera path file.

#include "core/io/camera_path_file.h"
#include "core/support/errors.h"
#include "fuzz/fuzz_input.h"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace triwalk;
  const std::filesystem::path path = fuzz::writeInput("path.txt", data, size);
  try {
    // A path read is one the viewer plays and render samples: the playback's
    // arithmetic must stay finite for any path the reader takes.
    const CameraPath cameraPath = readCameraPath(path);
    if (frameCount(cameraPath, 30.0) <= 10000) {
      for (const CameraPose& pose : framePoses(cameraPath, 30.0)) {
        if (!std::isfinite(pose.position.x + pose.position.y + pose.position.z + pose.yawDegrees + pose.pitchDegrees)) {
          __builtin_trap();
        }
      }
    }
  } catch (const InputError&) {
  }
  return 0;
}
