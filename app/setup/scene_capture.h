#pragma once
// Capture of a scene into a data set, as `capture` and `suite` run it:
// load the scene, open a headless GL context, find the walkable region of
// an imported scene (unless --area or --region gives one), render every
// view. Prints what it chose.

#include "app/setup/scene_loading.h"
#include "render/capture/dataset_capture.h"

#include <filesystem>
#include <string>
#include <vector>

namespace triwalk {

struct SceneCaptureRequest {
  std::string scene = "builtin";
  SceneImportArguments import;
  CaptureOptions options;  // options.region: given by --region
  bool autoArea = false;  // also for the built-in and JSON scenes, which state their own
  bool densityGiven = false;  // --spacing, --paths or --per-path: a generated floor keeps its own spacing otherwise
  std::vector<glm::vec2> starts;  // seeds of the automatic region (--start)
  std::string gl = "auto";
  std::string out;
};

CaptureSummary captureScene(const SceneCaptureRequest& request);

// Says, before a capture or an import into out begins, that out holds a
// data set and that it is replaced once the new one is complete (as a
// whole, never in part), naming what it holds; nothing otherwise.
void announceReplacedDataset(const std::filesystem::path& out, const char* command);

}  // namespace triwalk
