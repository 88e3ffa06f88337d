#pragma once
// `triwalk view`: the interactive walkthrough with its panels.

#include "app/viewer/view_overlay.h"
#include "core/geometry/camera_path.h"
#include "core/synthesis/view_synthesis.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace triwalk {

struct ViewerOptions {
  std::filesystem::path dataset;
  std::filesystem::path selection;  // empty: start from the dense triangulation
  int width = 1280, height = 720;
  size_t cacheBytes = size_t(1) << 30;
  // The live decimation's error panorama; 0: the selection's, if it says,
  // else decimate's defaults (the largest width not above
  // kDefaultErrorWidth that divides the data set's, every pixel).
  int errorWidth = 0;
  int errorStride = 0;
  SynthesisOptions synthesis;
  // Scripted use: render this many frames, 1/30 s of the clock each (the
  // path's playback, if any), wait for what the last one shows to load,
  // write a screenshot of the window and exit.
  int frames = 0;
  std::filesystem::path screenshot;
  CameraPath path;  // played from the start (app/viewer/walk_recording.h)
  std::string pathFile;
  std::filesystem::path record;  // record from the start, saved here
  bool hideUi = false;           // the view alone: no sidebar, hints or notices (an overlay keeps its colour bar)
  ViewOverlay overlay = ViewOverlay::None;
  // The tools sidebar at start; unset: as the person left it last time
  // (app/viewer/viewer_preferences.h).
  std::optional<bool> sidebar;
};

// Returns the process exit status.
int runViewer(const ViewerOptions& options);

}  // namespace triwalk
