#include "app/bench/bench_groups.h"
#include "app/bench/temporary_capture.h"
#include "core/io/exr_io.h"
#include "render/capture/dataset_capture.h"
#include "render/capture/panorama_capturer.h"
#include "scene/scene_description.h"

#include <filesystem>

namespace triwalk {

BenchViews captureBenchViews() {
  BenchViews views;
  views.scene = loadSceneDescription(builtinScenePath());
  views.positions = {{5.0f, 2.3f, 1.6f}, {5.35f, 2.3f, 1.6f}, {5.0f, 2.65f, 1.6f}, {5.35f, 2.65f, 1.6f}};
  views.destination = {5.12f, 2.45f, 1.6f};
  PanoramaCapturer capturer(views.scene, 1024);
  for (glm::vec3 position : views.positions) views.panoramas.push_back(capturer.capture(position));
  views.destinationPanorama = capturer.capture(views.destination);
  return views;
}

void benchCapture(BenchTable& table, const Scene& scene, int width, int count) {
  const std::string sceneSize = "builtin scene, " + std::to_string(scene.triangleCount()) + " triangles";
  const std::string panoramaSize = std::to_string(width) + "x" + std::to_string(width / 2);

  // End to end, as `triwalk capture` runs: render, read back, write EXR,
  // keep what a decimation reads (core/selection/selection_inputs.h).
  CaptureOptions options;
  options.width = width;
  options.probes = 0;
  options.paths = count / 4;
  options.perPath = 4;
  options.quiet = true;
  const CaptureSummary summary = TemporaryCapture(scene, options, "triwalk-bench-capture").summary();
  table.add({"capture throughput (render + read-back + OpenEXR write + the error-width copy and mesh)",
             panoramaSize + ", " + sceneSize + ", " + std::to_string(summary.samples) + " views",
             formatNumber(summary.samples / summary.seconds, 2) + " panoramas/s",
             "end to end; the write of one view overlaps the render of the next"});

  const CapturePlan plan = planCapture(scene, CaptureOptions{});
  PanoramaCapturer capturer(scene, width);
  capturer.capture(plan.samples[0].position);  // warm-up: shader compilation, first upload
  Panorama last;
  const auto start = BenchClock::now();
  for (int i = 0; i < count; ++i) {
    last = capturer.capture(plan.samples[size_t(i * 37) % plan.samples.size()].position);
  }
  const double renderSeconds = secondsSince(start);
  table.add({"capture render only (6 cube faces + resample + read-back)",
             panoramaSize + ", cube faces " + std::to_string(defaultCubeFaceSize(width)) + ", " + sceneSize + ", " +
                 std::to_string(count) + " views",
             formatNumber(count / renderSeconds, 2) + " panoramas/s",
             formatNumber(1000.0 * renderSeconds / count, 1) + " ms each; the last drew " +
                 std::to_string(capturer.trianglesDrawn()) + " triangles over its six faces"});

  const std::filesystem::path file = std::filesystem::temp_directory_path() / "triwalk-bench.exr";
  const int writes = 5;
  const auto writeStart = BenchClock::now();
  for (int i = 0; i < writes; ++i) writePanoramaExr(file, last);
  const double writeSeconds = secondsSince(writeStart) / writes;
  const auto bytes = std::filesystem::file_size(file);
  std::filesystem::remove(file);
  table.add({"capture OpenEXR write only (RGB half + Z float, ZIP)", panoramaSize,
             formatNumber(1000.0 * writeSeconds, 1) + " ms/panorama", formatNumber(double(bytes) / 1e6, 2) + " MB each"});
}

}  // namespace triwalk
