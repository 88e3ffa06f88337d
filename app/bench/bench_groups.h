#pragma once
// The groups of `triwalk bench`, one file each; they share the built-in
// scene captured once at the sizes they need.

#include "app/bench/bench_table.h"
#include "app/setup/scene_loading.h"
#include "core/image/image.h"
#include "core/io/dataset.h"
#include "core/selection/reference_selection.h"
#include "core/selection/triangle_error.h"
#include "scene/scene.h"

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace triwalk {

// Panoramas of the built-in scene around the middle of the walkable area,
// rendered once with the current GL context.
struct BenchViews {
  Scene scene;
  std::vector<glm::vec3> positions;  // sources, 0.35 m apart
  std::vector<Panorama> panoramas;   // 1024x512, one per position
  glm::vec3 destination{0.0f};       // inside the sources' triangle
  Panorama destinationPanorama;
};
BenchViews captureBenchViews();

void benchCapture(BenchTable& table, const Scene& scene, int width, int views);
void benchWarp(BenchTable& table, const BenchViews& views, int decimationWidth);
void benchRender(BenchTable& table, const BenchViews& views, int frames);
// The viewer's frame loop along a walk (selection empty: the dense mesh).
void benchViewer(BenchTable& table, const Dataset& dataset, const std::string& selection, int frames);
// The automatic walkable region of a scene (bench's default: the FZK house).
void benchRegion(BenchTable& table, const std::string& sceneSpec, const SceneImportArguments& import);
// The errors the decimation figures select with: decimate's --error-width
// and --error-stride.
struct BenchSelectionErrors {
  int width = kDefaultErrorWidth;
  int stride = kSelectionErrorStride;
  std::string describe() const;  // "errors at 256x128", and the lattice if any
};

// datasetDirectory empty: captures the default data set first.
void benchDecimate(BenchTable& table, const Scene& scene, const std::string& datasetDirectory,
                   const BenchSelectionErrors& errors);
// The decimation of the default capture's lattice and of one with 4x the
// samples over the same area, both captured at the error width: time and
// peak memory of each, and their ratios (issue 15's scaling row).
void benchScaling(BenchTable& table, const Scene& scene, const BenchSelectionErrors& errors);

// Tiled decimation of generated floors (builtin-floor:CxR each), captured
// at width, run as separate processes `jobs` at a time: time and each
// process's peak memory, and their growth from the first floor to the last;
// eval of each tiled selection; againstWhole: the first floor decimated
// untiled too.
void benchTiles(BenchTable& table, const std::vector<std::string>& floors, int width, int jobs, bool againstWhole);

// One decimation as the main job runs it (`decimate --max-error 1.85`):
// the panoramas loaded at the error width, the collapses, the refinement.
struct BenchDecimation {
  SelectionSettings settings;  // what the run selected with
  SelectionRun run;
  double loadSeconds = 0.0;
  double peakGigabytes = 0.0;  // resident, from the start of the load
  bool peakIsOwn = true;       // false: the kernel kept the process's earlier peak
  uint64_t layersComputed = 0, layersReused = 0;
  uint64_t layersWarpedAgain = 0;  // of layersComputed, those the cache had dropped for its budget
  double layerBudgetGigabytes = 0.0;
  // The kernel's share of the selection (getrusage, the whole process):
  // page faults and system CPU time, most of it faulting in fresh layers.
  uint64_t pageFaults = 0;
  double systemSeconds = 0.0;
};
BenchDecimation runBenchDecimation(const Dataset& dataset, const BenchSelectionErrors& errors);

using BenchClock = std::chrono::steady_clock;
inline double secondsSince(BenchClock::time_point start) {
  return std::chrono::duration<double>(BenchClock::now() - start).count();
}

}  // namespace triwalk
