#include "render/capture/dataset_capture.h"

#include "core/io/exr_io.h"
#include "core/io/staged_directory.h"
#include "core/selection/selection_inputs.h"
#include "core/support/errors.h"
#include "core/support/input_limits.h"
#include "core/support/progress.h"
#include "render/capture/panorama_capturer.h"

#include <cmath>
#include <cstdio>
#include <future>
#include <random>

namespace triwalk {

namespace {

// Uniform float in [0, 1) from a 32-bit engine, the same on every platform
// (std::uniform_real_distribution is not).
float unitRandom(std::mt19937& engine) { return float(engine() >> 8) * (1.0f / 16777216.0f); }

}  // namespace

namespace {

// A request is refused before anything is allocated for it: the plan holds
// a record per view.
void checkViewCount(double views, const std::string& option, const std::string& what) {
  if (!(views <= double(kMaxViews))) {
    char count[32];
    std::snprintf(count, sizeof count, "%.3g", views);
    throw InputError(option, std::string("gives ") + count + " " + what + "; a data set holds at most " +
                                 std::to_string(kMaxViews) + " views");
  }
}

// What the views' OpenEXR files take at least (half-float colour, float
// distance, compressed: about 4.4 bytes a pixel on the built-in scene,
// more on photographs), against the free space where they go: a request
// that cannot fit is refused before the first view is rendered.
void checkDiskSpace(const CapturePlan& plan, int width, const std::filesystem::path& outDirectory) {
  constexpr double kLeastBytesPerPixel = 4.0;
  const double views = double(plan.samples.size() + plan.probes.size());
  const double bytes = views * double(width) * double(width / 2) * kLeastBytesPerPixel;
  std::error_code error;
  std::filesystem::path folder = std::filesystem::absolute(outDirectory, error);
  while (!std::filesystem::exists(folder, error) && folder.has_relative_path()) folder = folder.parent_path();
  const std::filesystem::space_info space = std::filesystem::space(folder, error);
  if (!error && bytes > double(space.available)) {
    char text[160];
    std::snprintf(text, sizeof text, "%.0f views at %dx%d need about %.1f GiB on disk; %.1f GiB are free in %s", views,
                  width, width / 2, bytes / double(1 << 30), double(space.available) / double(1 << 30), folder.c_str());
    throw InputError(outDirectory.string(), text);
  }
}

// Samples on parallel paths across the rectangle.
void planRectangle(const CaptureOptions& options, CapturePlan& plan) {
  const glm::vec2 lower(plan.area.x, plan.area.y), upper(plan.area.z, plan.area.w);
  const glm::vec2 size = upper - lower;
  if (!(size.x > 0.0f && size.y > 0.0f)) throw InputError("--area", "x1 must exceed x0 and y1 must exceed y0");
  // Paths are parallel to the shorter side and spread along the longer.
  const bool pathsAlongY = size.y <= size.x;
  const float longSide = pathsAlongY ? size.x : size.y;
  const float shortSide = pathsAlongY ? size.y : size.x;
  if (options.spacing) {
    // Counted in double first: a tiny spacing overflows an int.
    const double paths = std::floor(double(longSide) / *options.spacing + 1e-4) + 1.0;
    const double perPath = std::floor(double(shortSide) / *options.spacing + 1e-4) + 1.0;
    checkViewCount(paths * perPath, "--spacing", "samples");
    plan.paths = int(paths);
    plan.perPath = int(perPath);
  } else {
    checkViewCount(double(options.paths) * double(options.perPath), "--paths/--per-path", "samples");
    plan.paths = options.paths;
    plan.perPath = options.perPath;
  }
  if (plan.paths < 2 || plan.perPath < 2) {
    throw InputError("--paths/--per-path", "need at least 2 paths of 2 samples to form triangles");
  }
  const float pathStep = options.spacing ? *options.spacing : longSide / float(plan.paths - 1);
  const float sampleStep = options.spacing ? *options.spacing : shortSide / float(plan.perPath - 1);
  plan.spacing = std::min(pathStep, sampleStep);
  // Centre the grid when a spacing leaves a margin.
  const float pathOffset = 0.5f * (longSide - pathStep * float(plan.paths - 1));
  const float sampleOffset = 0.5f * (shortSide - sampleStep * float(plan.perPath - 1));

  for (int path = 0; path < plan.paths; ++path) {
    for (int step = 0; step < plan.perPath; ++step) {
      const float along = pathOffset + pathStep * float(path);
      const float across = sampleOffset + sampleStep * float(step);
      const glm::vec2 xy = pathsAlongY ? lower + glm::vec2(along, across) : lower + glm::vec2(across, along);
      ViewRecord sample;
      sample.id = int(plan.samples.size());
      sample.file = sampleFileName(sample.id);
      sample.position = glm::vec3(xy, plan.eyeZ);
      sample.path = path;
      sample.step = step;
      plan.samples.push_back(sample);
    }
  }
}

// Samples on a square lattice over the region's bounds, kept where the
// region contains them; "path" and "step" are the lattice column and row,
// so the uniform baseline can take a coarser sub-lattice.
void planRegion(const CaptureOptions& options, const WalkableRegion& region, CapturePlan& plan) {
  glm::dvec2 lower, upper;
  region.bounds(lower, upper);
  plan.area = glm::vec4(lower.x, lower.y, upper.x, upper.y);
  const double spacing = options.spacing ? double(*options.spacing)
                                         : std::sqrt(region.area() / double(std::max(1, options.paths * options.perPath)));
  const glm::dvec2 extent = upper - lower;
  checkViewCount(std::ceil(extent.x / spacing) * std::ceil(extent.y / spacing), "--spacing", "lattice positions");
  plan.paths = std::max(1, int(std::ceil(extent.x / spacing - 1e-9)));
  plan.perPath = std::max(1, int(std::ceil(extent.y / spacing - 1e-9)));
  plan.spacing = float(spacing);
  // Centred in the bounds, so a lattice of cell centres stays on them.
  const glm::dvec2 margin = 0.5 * (extent - spacing * glm::dvec2(plan.paths - 1, plan.perPath - 1));
  for (int column = 0; column < plan.paths; ++column) {
    for (int row = 0; row < plan.perPath; ++row) {
      const glm::dvec2 xy = lower + margin + spacing * glm::dvec2(column, row);
      if (!region.contains(xy)) continue;
      ViewRecord sample;
      sample.id = int(plan.samples.size());
      sample.file = sampleFileName(sample.id);
      sample.position = glm::vec3(glm::vec2(xy), plan.eyeZ);
      sample.path = column;
      sample.step = row;
      plan.samples.push_back(sample);
    }
  }
  if (plan.samples.size() < 3) {
    throw InputError("--spacing", "leaves " + std::to_string(plan.samples.size()) +
                                      " samples inside the walkable region; at least 3 are needed (use a smaller spacing)");
  }
}

}  // namespace

CapturePlan planCapture(const Scene& scene, const CaptureOptions& options) {
  CapturePlan plan;
  const WalkableArea& walkable = scene.walkableArea;
  plan.area = options.area.value_or(glm::vec4(walkable.min, walkable.max));
  plan.eyeZ = walkable.floorHeight + options.eyeHeight.value_or(walkable.eyeHeight);
  if (options.width < 16 || options.width % 2 != 0) throw InputError("--width", "must be an even number >= 16");
  if (options.probes < 0) throw InputError("--probes", "must not be negative");
  if (options.spacing && !(*options.spacing > 0.0f)) throw InputError("--spacing", "must be positive");
  if (options.region && !options.area) {
    plan.region = options.region;
    planRegion(options, *options.region, plan);
  } else {
    planRectangle(options, plan);
  }

  // Probes: uniform in the region (the rectangle), never on top of a sample.
  const WalkableRegion region = plan.region ? *plan.region
                                            : WalkableRegion::rectangle({plan.area.x, plan.area.y}, {plan.area.z, plan.area.w});
  const glm::vec2 lower(plan.area.x, plan.area.y), size = glm::vec2(plan.area.z, plan.area.w) - lower;
  std::mt19937 engine(options.seed);
  const float minimumSeparation = 0.05f * plan.spacing;
  checkViewCount(double(plan.samples.size()) + double(options.probes), "--probes", "views");
  size_t tries = 0;
  while (int(plan.probes.size()) < options.probes) {
    if (++tries % 4096 == 0) throwIfInterrupted();
    const glm::vec2 xy = lower + glm::vec2(unitRandom(engine), unitRandom(engine)) * size;
    if (plan.region && !region.contains(glm::dvec2(xy))) continue;
    bool onSample = false;
    for (const ViewRecord& sample : plan.samples) {
      onSample |= glm::length(glm::vec2(sample.position) - xy) < minimumSeparation;
    }
    if (onSample) continue;
    ViewRecord probe;
    probe.id = int(plan.probes.size());
    probe.file = probeFileName(probe.id);
    probe.position = glm::vec3(xy, plan.eyeZ);
    plan.probes.push_back(probe);
  }
  return plan;
}

CaptureSummary captureDataset(const Scene& sceneWithDoors, const std::string& sceneName, const CaptureOptions& options,
                              const std::filesystem::path& outDirectory) {
  const bool hasDoors = sceneWithDoors.passableMeshCount() > 0;
  std::optional<Scene> doorsOpen;
  const Scene& scene = hasDoors && !options.closedDoors ? doorsOpen.emplace(withDoorsOpen(sceneWithDoors)) : sceneWithDoors;
  InterruptScope interruptScope;
  const CapturePlan plan = planCapture(scene, options);
  checkDiskSpace(plan, options.width, outDirectory);
  StagedDirectory staging(outDirectory, kManifestFileName, "a triwalk data set");
  createViewFolders(staging.path());

  CaptureSummary summary;
  {
    PanoramaCapturer capturer(scene, options.width, options.faceSize);
    summary.sceneTriangles = capturer.sceneTriangles();
    std::vector<const ViewRecord*> views;
    for (const ViewRecord& view : plan.samples) views.push_back(&view);
    for (const ViewRecord& view : plan.probes) views.push_back(&view);

    ProgressReporter progress("capture", views.size(), options.quiet);
    SelectionInputKeeper selectionInputs(staging.path(), glm::ivec2(options.width, options.width / 2));
    // The OpenEXR write of one view (and keeping what a decimation reads
    // of it) overlaps the rendering of the next.
    std::future<void> pendingWrite;
    int closeWarnings = 0;
    for (size_t index = 0; index < views.size(); ++index) {
      const ViewRecord* view = views[index];
      const bool isSample = index < plan.samples.size();
      throwIfInterrupted();
      Panorama panorama = capturer.capture(view->position);
      size_t tooClose = 0;
      for (float d : panorama.distance.pixels) tooClose += d < 0.05f;
      if (tooClose > panorama.distance.pixelCount() / 100 && closeWarnings++ < 5 && !options.quiet) {
        std::fprintf(stderr, "\ntriwalk: warning: view %s at (%.2f, %.2f, %.2f) is within 5 cm of geometry in %zu pixels "
                     "(inside an object?)\n",
                     view->file.c_str(), view->position.x, view->position.y, view->position.z, tooClose);
      }
      if (pendingWrite.valid()) pendingWrite.get();
      pendingWrite = std::async(std::launch::async, [&selectionInputs, path = staging.path() / view->file, view, isSample,
                                                     panorama = std::move(panorama)] {
        writePanoramaExr(path, panorama);
        selectionInputs.keep(*view, isSample, panorama);
      });
      progress.advance();
    }
    if (pendingWrite.valid()) pendingWrite.get();
    progress.finish();
    summary.seconds = progress.elapsedSeconds();

    Manifest manifest;
    manifest.scene = sceneName;
    manifest.width = options.width;
    manifest.height = options.width / 2;
    manifest.samples = plan.samples;
    manifest.probes = plan.probes;
    if (plan.region) manifest.walkable = *plan.region;
    manifest.capture = {{"paths", plan.paths},
                        {"per_path", plan.perPath},
                        {"area", {plan.area.x, plan.area.y, plan.area.z, plan.area.w}},
                        {"spacing", plan.spacing},
                        {"eye_z", plan.eyeZ},
                        {"face_size", options.faceSize > 0 ? options.faceSize : defaultCubeFaceSize(options.width)},
                        {"probe_seed", options.seed}};
    if (hasDoors) manifest.capture["doors"] = options.closedDoors ? "closed" : "open";
    if (!options.sceneSource.is_null()) manifest.capture["scene"] = options.sceneSource;
    writeManifest(staging.path(), manifest);
    staging.commit();
  }
  summary.samples = int(plan.samples.size());
  summary.probes = int(plan.probes.size());
  return summary;
}

}  // namespace triwalk
