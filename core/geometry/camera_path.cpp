#include "core/geometry/camera_path.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace triwalk {

namespace {

// When pose i is passed, from the path's start.
double timeOf(const CameraPath& path, size_t i, double framesPerSecond) {
  return path.timed() ? path.seconds[i] - path.seconds.front() : double(i) / framesPerSecond;
}

// The angle from a to b the short way round, in (-180, 180].
float turnDegrees(float from, float to) {
  float turn = std::fmod(to - from, 360.0f);
  if (turn > 180.0f) turn -= 360.0f;
  if (turn <= -180.0f) turn += 360.0f;
  return turn;
}

// Fritsch-Butland's weighted harmonic mean of the neighbouring slopes (the
// tangent of SciPy's PCHIP): zero where the slopes change sign or one is
// zero, so that the cubic stays between its ends.
double monotoneTangent(double slopeBefore, double slopeAfter, double stepBefore, double stepAfter) {
  if (slopeBefore * slopeAfter <= 0.0) return 0.0;
  return 3.0 * (stepBefore + stepAfter) /
         ((2.0 * stepAfter + stepBefore) / slopeBefore + (stepAfter + 2.0 * stepBefore) / slopeAfter);
}

}  // namespace

double pathDuration(const CameraPath& path, double framesPerSecond) {
  return path.poses.empty() ? 0.0 : timeOf(path, path.poses.size() - 1, framesPerSecond);
}

CameraPose poseAt(const CameraPath& path, double seconds, double framesPerSecond) {
  const size_t count = path.poses.size();
  if (count == 1 || seconds <= 0.0) return path.poses.front();
  if (seconds >= pathDuration(path, framesPerSecond)) return path.poses.back();
  // The segment [k, k + 1] holding the time.
  size_t k = 0;
  if (path.timed()) {
    const double absolute = path.seconds.front() + seconds;
    // Within the last segment even where the sum rounds onto the last time.
    k = std::min(size_t(std::upper_bound(path.seconds.begin(), path.seconds.end(), absolute) - path.seconds.begin()) - 1,
                 count - 2);
  } else {
    k = std::min(size_t(seconds * framesPerSecond), count - 2);
  }
  // Poses k - 1 .. k + 2 as far as they exist, yaw unwrapped from pose k - 1 on.
  const size_t first = k > 0 ? k - 1 : k, last = std::min(k + 2, count - 1);
  constexpr int kComponents = 5;
  std::array<std::array<double, kComponents>, 4> values{};
  std::array<double, 4> times{};
  float yaw = path.poses[first].yawDegrees;
  for (size_t i = first; i <= last; ++i) {
    const CameraPose& pose = path.poses[i];
    if (i > first) yaw += turnDegrees(path.poses[i - 1].yawDegrees, pose.yawDegrees);
    values[i - first] = {pose.position.x, pose.position.y, pose.position.z, yaw, pose.pitchDegrees};
    times[i - first] = timeOf(path, i, framesPerSecond);
  }
  const size_t a = k - first, b = a + 1;  // the segment's ends in values
  const double step = times[b] - times[a];
  const double s = std::clamp((seconds - timeOf(path, k, framesPerSecond)) / step, 0.0, 1.0);
  const double h00 = (2.0 * s - 3.0) * s * s + 1.0, h10 = ((s - 2.0) * s + 1.0) * s, h01 = (3.0 - 2.0 * s) * s * s,
               h11 = (s - 1.0) * s * s;
  std::array<double, kComponents> result{};
  for (int c = 0; c < kComponents; ++c) {
    const double slope = (values[b][c] - values[a][c]) / step;
    // One-sided at the path's ends.
    const double tangentA = a > 0 ? monotoneTangent((values[a][c] - values[a - 1][c]) / (times[a] - times[a - 1]), slope,
                                                    times[a] - times[a - 1], step)
                                  : slope;
    const double tangentB = k + 2 <= last ? monotoneTangent(slope, (values[b + 1][c] - values[b][c]) / (times[b + 1] - times[b]),
                                                            step, times[b + 1] - times[b])
                                          : slope;
    result[c] = h00 * values[a][c] + h10 * step * tangentA + h01 * values[b][c] + h11 * step * tangentB;
  }
  CameraPose pose;
  pose.position = glm::vec3(float(result[0]), float(result[1]), float(result[2]));
  pose.yawDegrees = float(std::fmod(std::fmod(result[3], 360.0) + 360.0, 360.0));
  pose.pitchDegrees = float(result[4]);
  return pose;
}

size_t frameCount(const CameraPath& path, double framesPerSecond) {
  if (!path.timed()) return path.poses.size();
  // Frames every 1 / framesPerSecond, and the end as one more unless it
  // falls within a millisecond of the last.
  const double duration = pathDuration(path, framesPerSecond);
  const double steps = std::floor(duration * framesPerSecond + 1e-3);
  return size_t(steps) + 1 + (steps / framesPerSecond < duration - 1e-3 ? 1 : 0);
}

std::vector<CameraPose> framePoses(const CameraPath& path, double framesPerSecond) {
  if (!path.timed()) return path.poses;
  const size_t frames = frameCount(path, framesPerSecond);
  std::vector<CameraPose> poses;
  poses.reserve(frames);
  for (size_t i = 0; i < frames; ++i) {
    poses.push_back(poseAt(path, std::min(double(i) / framesPerSecond, pathDuration(path, framesPerSecond)), framesPerSecond));
  }
  return poses;
}

void appendRecordedPose(CameraPath& path, const CameraPose& pose, double seconds) {
  auto same = [](const CameraPose& a, const CameraPose& b) {
    return a.position == b.position && a.yawDegrees == b.yawDegrees && a.pitchDegrees == b.pitchDegrees;
  };
  // Frames closer than a millisecond add nothing a playback could show.
  if (!path.seconds.empty() && seconds < path.seconds.back() + 1e-3) return;
  const size_t count = path.poses.size();
  if (count >= 2 && same(path.poses[count - 1], pose) && same(path.poses[count - 2], pose)) {
    path.seconds.back() = seconds;  // the pause goes on
    return;
  }
  path.poses.push_back(pose);
  path.seconds.push_back(seconds);
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
