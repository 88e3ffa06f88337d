#pragma once
// Capture of a scene into a data set, as `capture` and `suite` run it:
// load the scene, open a headless GL context, find the walkable area of an
// imported scene, render every view. Prints what it chose.

#include "app/setup/scene_loading.h"
#include "render/capture/dataset_capture.h"

#include <string>

namespace triwalk {

struct SceneCaptureRequest {
  std::string scene = "builtin";
  SceneImportArguments import;
  CaptureOptions options;
  bool autoArea = false;  // also for the built-in and JSON scenes, which state their own
  std::string gl = "auto";
  std::string out;
};

CaptureSummary captureScene(const SceneCaptureRequest& request);

}  // namespace triwalk
