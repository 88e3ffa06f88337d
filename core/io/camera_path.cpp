#include "core/io/camera_path.h"

#include "core/io/atomic_file.h"
#include "core/support/errors.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace triwalk {

std::vector<CameraPose> readCameraPath(const std::filesystem::path& path) {
  std::istringstream lines(readTextFile(path));
  std::vector<CameraPose> poses;
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const size_t comment = line.find('#');
    if (comment != std::string::npos) line.resize(comment);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(line);
    CameraPose pose;
    std::string extra;
    if (!(fields >> pose.position.x >> pose.position.y >> pose.position.z >> pose.yawDegrees >> pose.pitchDegrees) ||
        (fields >> extra)) {
      throw InputError(path.string(), "line " + std::to_string(number) + ": expected 'x y z yaw pitch', got '" + line + "'");
    }
    if (!std::isfinite(pose.position.x) || !std::isfinite(pose.position.y) || !std::isfinite(pose.position.z) ||
        !std::isfinite(pose.yawDegrees) || !std::isfinite(pose.pitchDegrees) || std::abs(pose.pitchDegrees) >= 90.0f) {
      throw InputError(path.string(), "line " + std::to_string(number) + ": values must be finite, |pitch| < 90");
    }
    poses.push_back(pose);
  }
  if (poses.empty()) throw InputError(path.string(), "no poses in the camera path");
  return poses;
}

void writeCameraPath(const std::filesystem::path& path, const std::vector<CameraPose>& poses) {
  std::string text = "# x y z yaw pitch (metres, degrees)\n";
  char line[128];
  for (const CameraPose& pose : poses) {
    std::snprintf(line, sizeof line, "%.4f %.4f %.4f %.3f %.3f\n", pose.position.x, pose.position.y, pose.position.z,
                  pose.yawDegrees, pose.pitchDegrees);
    text += line;
  }
  writeTextFileAtomically(path, text);
}

std::vector<CameraPose> rotatePath(glm::vec3 at, int frames, float pitchDegrees) {
  std::vector<CameraPose> poses;
  for (int i = 0; i < frames; ++i) poses.push_back({at, 360.0f * float(i) / float(frames), pitchDegrees});
  return poses;
}

std::vector<CameraPose> translatePath(glm::vec3 from, glm::vec3 to, int frames, float yawDegrees, float pitchDegrees) {
  std::vector<CameraPose> poses;
  for (int i = 0; i < frames; ++i) {
    const float t = frames > 1 ? float(i) / float(frames - 1) : 0.0f;
    poses.push_back({from + t * (to - from), yawDegrees, pitchDegrees});
  }
  return poses;
}

}  // namespace triwalk
