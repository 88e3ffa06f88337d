#include "app/viewer/walk_recording.h"

#include "core/io/camera_path_file.h"

#include <cstdio>
#include <exception>

namespace triwalk {

namespace {

std::string describePath(const CameraPath& path) {
  char text[96];
  std::snprintf(text, sizeof text, "%zu pose%s, %.1f s", path.poses.size(), path.poses.size() == 1 ? "" : "s",
                pathDuration(path, kPathFramesPerSecond));
  return text;
}

}  // namespace

CameraPose poseOf(const WalkState& state) { return {state.position, state.yawDegrees, state.pitchDegrees}; }

void moveTo(WalkState& state, const CameraPose& pose) {
  state.position = pose.position;
  state.yawDegrees = pose.yawDegrees;
  state.pitchDegrees = pose.pitchDegrees;
}

void toggleRecording(WalkRecording& walk, double clock) {
  if (walk.recordingSince) {
    walk.recordingSince.reset();
    if (walk.recording.poses.empty()) return;
    walk.path = std::move(walk.recording);
    walk.recording = {};
    walk.source = "recorded";
    saveWalk(walk);
    return;
  }
  walk.recording = {};
  walk.recordingSince = clock;
  walk.message = "recording (R ends it and saves it to " + walk.file + ")";
}

void togglePlayback(WalkRecording& walk, double clock) {
  if (walk.playingSince) {
    walk.playingSince.reset();
    walk.message = "stopped playing";
    return;
  }
  if (walk.path.poses.empty()) {
    walk.message = "no walk to play: R records one, or load a file";
    return;
  }
  walk.playingSince = clock;
  walk.message = "playing " + describePath(walk.path);
}

bool saveWalk(WalkRecording& walk) {
  if (walk.path.poses.empty()) {
    walk.message = "no walk to save: R records one";
    return false;
  }
  try {
    writeCameraPath(walk.file, walk.path);
  } catch (const std::exception& error) {
    walk.message = std::string("not saved: ") + error.what();
    return false;
  }
  walk.message = "saved " + describePath(walk.path) + " to " + walk.file;
  std::printf("saved the walk (%s) to %s\n", describePath(walk.path).c_str(), walk.file.c_str());
  std::fflush(stdout);
  return true;
}

bool loadWalk(WalkRecording& walk) {
  try {
    walk.path = readCameraPath(walk.file);
  } catch (const std::exception& error) {
    walk.message = std::string("not loaded: ") + error.what();
    return false;
  }
  walk.playingSince.reset();
  walk.source = walk.file;
  walk.message = "loaded " + describePath(walk.path) + " (P plays it)";
  return true;
}

bool followPlayback(WalkRecording& walk, double clock, WalkState& state) {
  if (!walk.playingSince) return false;
  const double seconds = clock - *walk.playingSince;
  moveTo(state, poseAt(walk.path, seconds, kPathFramesPerSecond));
  if (seconds >= pathDuration(walk.path, kPathFramesPerSecond)) {
    walk.playingSince.reset();  // this frame shows the end
    walk.message = "played " + describePath(walk.path);
  }
  return true;
}

void recordFrame(WalkRecording& walk, double clock, const WalkState& state) {
  if (walk.recordingSince) appendRecordedPose(walk.recording, poseOf(state), clock - *walk.recordingSince);
}

}  // namespace triwalk
