#pragma once
// Camera paths: poses a walker passes through, either one pose a frame or
// each at a recorded time (a walk recorded in the viewer), and how a path
// is played: smoothly and in time, passing through every pose. The
// presets of the paper's figures: rotating at a point (Fig. 7) and
// translating along a line (Fig. 8).

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace triwalk {

struct CameraPose {
  glm::vec3 position{0.0f};
  float yawDegrees = 0.0f;
  float pitchDegrees = 0.0f;
};

struct CameraPath {
  std::vector<CameraPose> poses;
  // When each pose is passed, in seconds, increasing; empty: one pose a
  // frame, whatever the frame rate.
  std::vector<double> seconds;

  bool timed() const { return !seconds.empty(); }
};

// How long a path plays: from its first recorded time to its last, or, one
// pose a frame, (poses - 1) frames.
double pathDuration(const CameraPath& path, double framesPerSecond);

// The pose `seconds` after the path's start (clamped to its ends). Between
// poses, each of x, y, z, yaw and pitch follows a monotone cubic in time
// (Fritsch and Carlson 1980): it passes through every pose exactly, is
// smooth, and never overshoots between two poses, so a pause stays still
// and a walk does not swing past a corner or through a wall it went
// around. Yaw turns the short way round.
CameraPose poseAt(const CameraPath& path, double seconds, double framesPerSecond);

// How many frames framePoses gives (a caller bounds it before asking).
size_t frameCount(const CameraPath& path, double framesPerSecond);

// The most frames a render or a video export of a path makes: an hour at
// 30 frames a second.
inline constexpr size_t kMaxPathFrames = 108000;

// The frames of a video or a headless render at framesPerSecond: the poses
// themselves for a path of one pose a frame; for a timed path, poseAt every
// 1 / framesPerSecond seconds from its start to its end (its end included).
std::vector<CameraPose> framePoses(const CameraPath& path, double framesPerSecond);

// Recording: adds the pose passed `seconds` after the recording's start
// (a frame within a millisecond of the last is skipped). A pause is kept as its first and last pose, not
// as every frame in between: the playback stays still between two equal
// poses.
void appendRecordedPose(CameraPath& path, const CameraPose& pose, double seconds);

// A full turn at a point, frames evenly spaced from yaw 0.
std::vector<CameraPose> rotatePath(glm::vec3 at, int frames, float pitchDegrees = 0.0f);
// From one point to another (inclusive), looking at a fixed yaw.
std::vector<CameraPose> translatePath(glm::vec3 from, glm::vec3 to, int frames, float yawDegrees, float pitchDegrees = 0.0f);

}  // namespace triwalk
