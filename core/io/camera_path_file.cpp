#include "core/io/camera_path_file.h"

#include "core/io/atomic_file.h"
#include "core/support/errors.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace triwalk {

namespace {

constexpr double kMaxPathCoordinate = 1e7, kMaxPathYawDegrees = 1e6, kMaxPathSeconds = 1e6;
// writeCameraPath keeps microseconds; half of one, so that rounding never refuses a written file.
constexpr double kMinPathSecondsApart = 0.5e-6;

}  // namespace

CameraPath readCameraPath(const std::filesystem::path& path) {
  std::istringstream lines(readTextFile(path));
  CameraPath cameraPath;
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const size_t comment = line.find('#');
    if (comment != std::string::npos) line.resize(comment);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    auto fail = [&](const std::string& problem) {
      throw InputError(path.string(), "line " + std::to_string(number) + ": " + problem);
    };
    std::istringstream fields(line);
    CameraPose pose;
    double seconds = 0.0;
    std::string extra;
    if (!(fields >> pose.position.x >> pose.position.y >> pose.position.z >> pose.yawDegrees >> pose.pitchDegrees)) {
      fail("expected 'x y z yaw pitch [seconds]', got '" + line + "'");
    }
    const bool timed = bool(fields >> seconds);
    if (!timed && !fields.eof()) fail("expected 'x y z yaw pitch [seconds]', got '" + line + "'");
    if (timed && (fields >> extra)) fail("expected 'x y z yaw pitch [seconds]', got '" + line + "'");
    // Bounds that keep the playback's arithmetic exact enough (core/geometry/camera_path.h).
    auto within = [](double value, double bound) { return std::isfinite(value) && std::abs(value) <= bound; };
    if (!within(pose.position.x, kMaxPathCoordinate) || !within(pose.position.y, kMaxPathCoordinate) ||
        !within(pose.position.z, kMaxPathCoordinate) || !within(pose.yawDegrees, kMaxPathYawDegrees) ||
        !(std::abs(pose.pitchDegrees) < 90.0f) || !within(seconds, kMaxPathSeconds) || seconds < 0.0) {
      fail("values must be finite, |x|, |y|, |z| <= 1e7 m, |yaw| <= 1e6 deg, |pitch| < 90 deg, 0 <= seconds <= 1e6");
    }
    if (!cameraPath.poses.empty() && timed != cameraPath.timed()) {
      fail("seconds must be given on every line or on none");
    }
    if (timed) {
      if (!cameraPath.seconds.empty() && !(seconds - cameraPath.seconds.back() >= kMinPathSecondsApart)) {
        fail("seconds must increase from line to line, by at least a microsecond");
      }
      cameraPath.seconds.push_back(seconds);
    }
    cameraPath.poses.push_back(pose);
  }
  if (cameraPath.poses.empty()) throw InputError(path.string(), "no poses in the camera path");
  return cameraPath;
}

void writeCameraPath(const std::filesystem::path& path, const CameraPath& cameraPath) {
  std::string text = cameraPath.timed() ? "# x y z yaw pitch seconds (metres, degrees)\n" : "# x y z yaw pitch (metres, degrees)\n";
  for (size_t i = 0; i < cameraPath.poses.size(); ++i) {
    const CameraPose& pose = cameraPath.poses[i];
    // Room for five floats as large as they come.
    char line[512];
    std::snprintf(line, sizeof line, "%.4f %.4f %.4f %.3f %.3f", pose.position.x, pose.position.y, pose.position.z,
                  pose.yawDegrees, pose.pitchDegrees);
    text += line;
    if (cameraPath.timed()) {
      // Microseconds: recorded frames are far further apart, so the times stay increasing.
      std::snprintf(line, sizeof line, " %.6f", cameraPath.seconds[i]);
      text += line;
    }
    text += '\n';
  }
  writeTextFileAtomically(path, text);
}

}  // namespace triwalk
