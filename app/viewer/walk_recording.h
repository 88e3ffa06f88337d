#pragma once
// Walks in the viewer: R records the walk (each frame's pose at its time),
// P plays the walk back in real time along core/geometry/camera_path.h's
// smooth curve through every recorded pose, and the walk is saved and
// loaded in the camera path format `render --path` reads. Times run on the
// viewer's clock: wall time, or 1/30 s a frame in scripted runs (--frames),
// so that those repeat exactly.

#include "app/viewer/walk_controller.h"
#include "core/geometry/camera_path.h"

#include <optional>
#include <string>

namespace triwalk {

// A path without times plays at this many poses a second, as render's
// default --fps; scripted frames advance the clock by its inverse.
constexpr double kPathFramesPerSecond = 30.0;

struct WalkRecording {
  CameraPath path;       // the walk to play, save and export: recorded, loaded, or given with --path
  CameraPath recording;  // while recording: what was walked so far (a playback can be recorded too)
  std::string source;  // where the path came from, for the panel
  std::optional<double> recordingSince, playingSince;  // the viewer's clock when they started
  std::string file = "walk.txt";                       // saved to and loaded from
  std::string videoFile = "walk.mp4";                   // the path's video export
  std::string message;                                 // the last thing done, or what failed
};

// R: starts a new recording, or ends it: it becomes the path, saved to `file`.
void toggleRecording(WalkRecording& walk, double clock);
// P: plays the path from its start, or stops it there.
void togglePlayback(WalkRecording& walk, double clock);
bool saveWalk(WalkRecording& walk);
bool loadWalk(WalkRecording& walk);

// Each frame, before it is drawn: a playing path sets the walker's pose
// (true while it plays, the walker's own input ignored), and a recording
// keeps the pose the frame shows.
bool followPlayback(WalkRecording& walk, double clock, WalkState& state);
void recordFrame(WalkRecording& walk, double clock, const WalkState& state);

// The pose a walk state stands for, and back.
CameraPose poseOf(const WalkState& state);
void moveTo(WalkState& state, const CameraPose& pose);

}  // namespace triwalk
