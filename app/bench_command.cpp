// `triwalk bench`: every performance figure the project quotes comes from
// here, printed with the machine and the data size.

#include "app/bench_table.h"
#include "app/commands.h"
#include "core/exr_io.h"
#include "render/dataset_capture.h"
#include "render/gl_context.h"
#include "render/panorama_capturer.h"
#include "render/scene_description.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>

namespace triwalk {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void benchCapture(BenchTable& table, int width, int count) {
  const Scene scene = loadSceneDescription(builtinScenePath());
  const std::string sceneSize = "builtin scene, " + std::to_string(scene.triangleCount()) + " triangles";
  const std::string panoramaSize = std::to_string(width) + "x" + std::to_string(width / 2);

  // End to end, as `triwalk capture` runs: render, read back, write EXR.
  CaptureOptions options;
  options.width = width;
  options.probes = 0;
  options.paths = count / 4;
  options.perPath = 4;
  options.quiet = true;
  const std::filesystem::path directory = std::filesystem::temp_directory_path() / "triwalk-bench-capture";
  const CaptureSummary summary = captureDataset(scene, "builtin", options, directory);
  std::filesystem::remove_all(directory);
  table.add({"capture throughput (render + read-back + OpenEXR write)",
             panoramaSize + ", " + sceneSize + ", " + std::to_string(summary.samples) + " views",
             formatNumber(summary.samples / summary.seconds, 2) + " panoramas/s",
             "end to end; the write of one view overlaps the render of the next"});

  const CapturePlan plan = planCapture(scene, CaptureOptions{});
  PanoramaCapturer capturer(scene, width);
  capturer.capture(plan.samples[0].position);  // warm-up: shader compilation, first upload
  Panorama last;
  const auto start = Clock::now();
  for (int i = 0; i < count; ++i) {
    last = capturer.capture(plan.samples[size_t(i * 37) % plan.samples.size()].position);
  }
  const double renderSeconds = secondsSince(start);
  table.add({"capture render only (6 cube faces + resample + read-back)",
             panoramaSize + ", cube faces " + std::to_string(defaultCubeFaceSize(width)) + ", " + sceneSize + ", " +
                 std::to_string(count) + " views",
             formatNumber(count / renderSeconds, 2) + " panoramas/s",
             formatNumber(1000.0 * renderSeconds / count, 1) + " ms each"});

  const std::filesystem::path file = std::filesystem::temp_directory_path() / "triwalk-bench.exr";
  const int writes = 5;
  const auto writeStart = Clock::now();
  for (int i = 0; i < writes; ++i) writePanoramaExr(file, last);
  const double writeSeconds = secondsSince(writeStart) / writes;
  const auto bytes = std::filesystem::file_size(file);
  std::filesystem::remove(file);
  table.add({"capture OpenEXR write only (RGB half + Z float, ZIP)", panoramaSize,
             formatNumber(1000.0 * writeSeconds, 1) + " ms/panorama", formatNumber(double(bytes) / 1e6, 2) + " MB each"});
}

}  // namespace

void registerBenchCommand(CLI::App& app) {
  struct Arguments {
    std::vector<std::string> only;
    std::string gl = "auto";
    int captureViews = 20;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("bench", "Measure throughput and print a table (machine, sizes, figures)");
  command->add_option("--only", arguments->only, "Run only these groups: capture")->delimiter(',');
  command->add_option("--gl", arguments->gl, "Headless OpenGL: auto, egl or osmesa")->capture_default_str();
  command->add_option("--capture-views", arguments->captureViews, "Panoramas rendered for the capture figure")
      ->capture_default_str()->check(CLI::PositiveNumber);
  command->callback([arguments] {
    const std::set<std::string> only(arguments->only.begin(), arguments->only.end());
    auto selected = [&](const std::string& group) { return only.empty() || only.count(group) > 0; };
    BenchTable table;
    std::string glDescription;
    auto context = createHeadlessContext(parseHeadlessBackend(arguments->gl));
    glDescription = context->description();
    if (selected("capture")) benchCapture(table, 1024, arguments->captureViews);
    table.print(glDescription);
  });
}

}  // namespace triwalk
