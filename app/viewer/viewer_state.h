#pragma once
// What the viewer's panels show and change, in one place: each panel is a
// function of this state (SIBR's onGUI), the app updates and renders it.

#include "app/viewer/decimation_session.h"
#include "app/viewer/gl_image.h"
#include "app/viewer/view_overlay.h"
#include "app/viewer/walk_controller.h"
#include "app/viewer/walk_recording.h"
#include "core/geometry/view_mesh.h"
#include "core/selection/reference_selection.h"
#include "render/walkthrough/frame_scale.h"
#include "render/walkthrough/gpu_warper.h"
#include "render/walkthrough/panorama_cache.h"

#include <array>
#include <optional>
#include <string>

namespace triwalk {

struct ViewerState {
  const Dataset* dataset = nullptr;
  DecimationSession* session = nullptr;
  DecimationSession::Snapshot snapshot;
  ViewMesh mesh;

  WalkState walk;
  // The viewer's clock, seconds: wall time, or 1/30 s a frame in scripted
  // runs (app/viewer/walk_recording.h).
  double clock = 0.0;
  bool scripted = false;  // --frames: what depends on timing stays off screen
  WalkRecording walkPath;
  bool exportRequested = false;  // the walk panel's "export video"
  size_t exportFrame = 0, exportFrames = 0;  // while exporting
  float verticalFovDegrees = 60.0f;
  float renderScale = 1.0f;  // share of each side of the window the warp renders, at most
  // While the camera moves, fewer pixels so that the warp fits the budget
  // (render/walkthrough/frame_scale.h); full resolution once it stops.
  bool holdFrameBudget = true;
  float frameBudgetMilliseconds = float(kWalkFrameBudgetMilliseconds);
  float currentScale = 1.0f;  // of the frame on screen
  GpuWarpSettings warp;
  float grazingAngleDegrees = WarpOptions{}.grazingAngleDegrees;
  bool stretchChanged = false;  // apply: reload panoramas with the new stretch test

  int currentTriangle = -1;
  std::array<int, 3> references{-1, -1, -1};
  int referencesAvailable = 0;
  int selectedTriangle = -1;

  // Decimation panel inputs.
  int stepCount = 10;
  // "run to error": an absolute error, or (runRelative) a factor of the
  // dense triangulation's mean error, as decimate's --max-error and
  // --relative-error; the viewer starts them at the selection's threshold.
  bool runRelative = true;
  float runError = float(kPaperMaxError);
  float runRelativeError = float(kDefaultRelativeError);
  int runSamples = 21;
  std::string savePath = "selection.json";
  std::string message;

  // Inspector.
  std::optional<DecimationSession::Inspection> inspection;
  GlImage reconstructionImage, truthImage, heatmapImage;

  // Statistics.
  double smoothedFrameSeconds = 0.0;  // between frames, moving average: fps = 1 / this
  double frameMilliseconds = 0.0;     // this frame's own work
  PanoramaCache::Statistics cache;
  GpuFrameStatistics frame;

  // The view's overlay (T, E) and what its legend says.
  ViewOverlay overlay = ViewOverlay::None;
  std::string overlayNote;
  GlImage errorOverlayImage;  // the error overlay's heatmap panorama

  bool sidebar = false;  // the tools beside the 3D view (Tab)
  bool help = false;     // the list of keys over the view (F1, ?)
  bool screenshotRequested = false;
  std::string screenshotPath;
};

void drawMapPanel(ViewerState& state);
void drawDecimationPanel(ViewerState& state);
void drawInspectorPanel(ViewerState& state);
void drawRenderPanel(ViewerState& state);
void drawWalkPanel(ViewerState& state);

}  // namespace triwalk
