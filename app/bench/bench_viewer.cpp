#include "app/bench/bench_groups.h"
#include "app/setup/walkthrough_setup.h"
#include "core/geometry/camera_path.h"
#include "core/synthesis/simplified_mesh_store.h"
#include "render/walkthrough/frame_scale.h"
#include "render/walkthrough/walkthrough_renderer.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <optional>
#include <thread>

namespace triwalk {

namespace {

struct Walk {
  std::vector<double> milliseconds;
  double meanScale = 0.0;
  int incomplete = 0;  // frames drawn with a reference still loading
  // Frames with none of their references yet: nothing is drawn, so they are
  // not timed (a walk that outruns the loader would otherwise show 0 ms).
  int empty = 0;
  PanoramaCache::Statistics cache;
};

// One walk from an empty working set, at full resolution or with the
// viewer's frame budget (render/walkthrough/frame_scale.h).
Walk walk(const Dataset& dataset, const ViewMesh& mesh, const std::vector<CameraPose>& poses, SourceMesh sourceMesh,
          bool holdBudget) {
  WarpOptions warpOptions;
  warpOptions.mesh = sourceMesh;
  PanoramaCache cache(dataset, warpOptions, size_t(1) << 30, kMinimumWalkingScale);
  WalkthroughRenderer renderer(mesh, cache, 1280, 720);
  FrameScaleController frameScale(kWalkFrameBudgetMilliseconds, kMinimumWalkingScale);
  Walk result;
  for (const CameraPose& pose : poses) {
    const float scale = holdBudget ? frameScale.movingScale(1.0f) : 1.0f;
    PinholeCamera camera;
    camera.width = int(1280.0f * scale);
    camera.height = int(720.0f * scale);
    camera.position = pose.position;
    camera.yawDegrees = pose.yawDegrees;
    glFinish();
    const auto start = BenchClock::now();
    const WalkthroughRenderer::Frame frame = renderer.render(camera, GpuWarpSettings{}, false, false, scale);
    glFinish();
    const double elapsed = secondsSince(start);
    if (frame.available > 0) {
      frameScale.record(scale, 1000.0 * elapsed, frame.available == 3);
      result.milliseconds.push_back(1000.0 * elapsed);
    } else {
      ++result.empty;
    }
    result.meanScale += scale / double(poses.size());
    result.incomplete += frame.available < 3;
    // The walk advances at 30 frames a second at most, as a display would.
    if (elapsed < 1.0 / 30.0) std::this_thread::sleep_for(std::chrono::duration<double>(1.0 / 30.0 - elapsed));
  }
  result.cache = cache.statistics();
  return result;
}

// Walks of the default row pooled into one: their frames together, the
// mean scale over all of them, their counts summed.
constexpr int kPooledWalks = 3;
Walk pooled(const std::vector<Walk>& walks) {
  Walk all;
  for (const Walk& one : walks) {
    all.milliseconds.insert(all.milliseconds.end(), one.milliseconds.begin(), one.milliseconds.end());
    all.meanScale += one.meanScale / double(walks.size());
    all.incomplete += one.incomplete;
    all.empty += one.empty;
    all.cache.hits += one.cache.hits;
    all.cache.misses += one.cache.misses;
    all.cache.meshesRead += one.cache.meshesRead;
    all.cache.meshesSimplified += one.cache.meshesSimplified;
  }
  return all;
}

// What the loader thread does for one reference (decode, warp source,
// tiles), for the walk's first references: the grid, a simplification, and
// a simplification read from the data set's mesh store.
void benchReferencePreparation(BenchTable& table, const Dataset& dataset, const ViewMesh& mesh) {
  const std::vector<int> references(
      mesh.vertices().begin(), mesh.vertices().begin() + std::min<ptrdiff_t>(3, ptrdiff_t(mesh.vertices().size())));
  const std::string size = std::to_string(dataset.manifest().width) + "x" + std::to_string(dataset.manifest().height) +
                           ", mean of " + std::to_string(references.size()) + " references";
  SimplifiedMeshStore store(dataset);
  WarpOptions simplified;
  simplified.mesh = SourceMesh::Simplified;
  struct Way {
    std::string name;
    std::function<WarpSource(const ViewRecord&, const Panorama&)> source;
    bool walking = false;  // and the walking mesh, from the store (filled by the first way that asks)
  };
  const auto yaw = [](const ViewRecord& view) { return degreesToRadians(view.yawDegrees); };
  const std::vector<Way> ways = {
      {"grid",
       [&](const ViewRecord& v, const Panorama& p) { return WarpSource(p, v.position, yaw(v), WarpOptions{}); }},
      {"simplified now",
       [&](const ViewRecord& v, const Panorama& p) { return WarpSource(p, v.position, yaw(v), simplified); }},
      {"simplified, read from the data set's mesh store",
       [&](const ViewRecord& v, const Panorama& p) { return store.source(v, p, simplified); }},
      {"simplified, read from the store, and its walking mesh made and stored",
       [&](const ViewRecord& v, const Panorama& p) { return store.source(v, p, simplified); }, true},
      {"simplified and its walking mesh, both read from the store",
       [&](const ViewRecord& v, const Panorama& p) { return store.source(v, p, simplified); }, true},
  };
  // The walking meshes are made again for the first way that asks.
  for (const int sample : references) {
    const ViewRecord& view = dataset.sample(sample);
    std::filesystem::remove(
        store.file(view, dataset.manifest().width, simplified.meshTolerancePixels, kMinimumWalkingScale));
  }
  for (const Way& way : ways) {
    double decodeSeconds = 0.0, sourceSeconds = 0.0, totalSeconds = 0.0;
    size_t triangles = 0, walkingTriangles = 0;
    for (const int sample : references) {
      const ViewRecord& view = dataset.sample(sample);
      const auto start = BenchClock::now();
      const Panorama panorama = dataset.loadView(view);
      decodeSeconds += secondsSince(start);
      const auto sourceStart = BenchClock::now();
      const WarpSource source = way.source(view, panorama);
      sourceSeconds += secondsSince(sourceStart);
      std::optional<WalkingMesh> walking;
      if (way.walking) {
        walking = WalkingMesh{store.walkingTriangles(view, panorama, source, simplified, kMinimumWalkingScale),
                              kMinimumWalkingScale};
      }
      const PreparedPanorama prepared = preparePanorama(panorama, yaw(view), source, walking ? &*walking : nullptr);
      totalSeconds += secondsSince(start);
      const auto count = [](const std::vector<PanoramaTile>& tiles) {
        size_t indices = 0;
        for (const PanoramaTile& tile : tiles) indices += size_t(tile.indexCount);
        return indices / 3;
      };
      triangles += count(prepared.tiles);
      walkingTriangles += count(prepared.walkingTiles);
    }
    const double n = double(references.size());
    table.add({"reference preparation on the viewer's loader thread (" + way.name + ")", size,
               formatNumber(1000.0 * totalSeconds / n, 0) + " ms",
               "of which decoding the EXR " + formatNumber(1000.0 * decodeSeconds / n, 0) + " ms, the warp source " +
                   formatNumber(1000.0 * sourceSeconds / n, 0) + " ms, then the walking mesh and the GPU tiles; " +
                   formatNumber(double(triangles) / n, 0) + " triangles" +
                   (walkingTriangles > 0 ? ", walking mesh " + formatNumber(double(walkingTriangles) / n, 0) : "")});
  }
}

// Issue 71: the holes the triangle's references leave before the fill,
// resolved from the neighbouring triangles' three nearest references or
// not, along render's rotate and translate paths of the selection (every
// panorama waited for, full resolution, simplified meshes): the fraction of
// pixels the fill paints, and the frame time it costs.
void benchHolesFromNeighbours(BenchTable& table, const Dataset& dataset, const ViewMesh& mesh) {
  glm::dvec2 lower(1e30), upper(-1e30);
  for (int v : mesh.vertices()) lower = glm::min(lower, mesh.position(v)), upper = glm::max(upper, mesh.position(v));
  const float eye = sampleEyeHeight(dataset);
  const glm::vec3 middle(glm::vec2(0.5 * (lower + upper)), eye);
  std::vector<CameraPose> poses = rotatePath(middle, 36);
  const std::vector<CameraPose> across =
      translatePath({float(lower.x), middle.y, eye}, {float(upper.x), middle.y, eye}, 24, 90.0f);
  poses.insert(poses.end(), across.begin(), across.end());
  WarpOptions warpOptions;
  warpOptions.mesh = SourceMesh::Simplified;
  PanoramaCache cache(dataset, warpOptions, size_t(1) << 30);
  WalkthroughRenderer renderer(mesh, cache, 1280, 720);
  struct Way {
    double holes = 0.0;  // mean fraction of the frame's pixels
    int framesWithHoles = 0;
    std::vector<double> milliseconds;
  };
  auto run = [&](bool neighbours) {
    GpuWarpSettings settings;
    settings.holesFromNeighbours = neighbours;
    Way way;
    for (const CameraPose& pose : poses) {
      PinholeCamera camera;
      camera.position = pose.position;
      camera.yawDegrees = pose.yawDegrees;
      renderer.render(camera, settings, true);  // loads the panoramas
      glFinish();
      const auto start = BenchClock::now();
      renderer.render(camera, settings, true);
      glFinish();
      way.milliseconds.push_back(1000.0 * secondsSince(start));
      const GpuHoleCounts holes = renderer.warper().countHoles();
      way.holes += double(holes.holesBefore) / double(holes.pixels) / double(poses.size());
      way.framesWithHoles += holes.holesBefore > 0;
    }
    return way;
  };
  const Way without = run(false), with = run(true);
  const std::string size = "1280x720, render's rotate (36) and translate (24) paths, " +
                           std::to_string(mesh.vertexCount()) + " references of " +
                           std::to_string(dataset.manifest().width) + "x" + std::to_string(dataset.manifest().height);
  table.add({"holes before the fill: the triangle's references alone / and the neighbours' three nearest", size,
             formatNumber(100.0 * without.holes, 3) + "% / " + formatNumber(100.0 * with.holes, 3) + "% of the pixels",
             "frames with holes " + std::to_string(without.framesWithHoles) + " / " + std::to_string(with.framesWithHoles) +
                 " of " + std::to_string(poses.size())});
  table.add({"frame time with holes resolved from the neighbours, median / p95 (without: the triangle's alone)", size,
             formatMedianAndP95(with.milliseconds),
             "without: " + formatMedianAndP95(without.milliseconds) + "; simplified meshes, full resolution"});
}

}  // namespace

// The viewer's frame loop without the window: walking along a line at
// 1.2 m/s and 30 frames a second, panoramas from the working set that never
// blocks (a reference still loading is drawn without); with the exact grids
// and with simplified meshes, each at full resolution and with the frame
// budget the viewer walks with by default (the viewer's own way, simplified
// meshes under the budget, kPooledWalks times). Simplified meshes walk once
// more first, with the data set's mesh store as found, which fills it.
void benchViewer(BenchTable& table, const Dataset& dataset, const std::string& selection, int frames) {
  const ViewMesh mesh = walkthroughMesh(dataset, selection);
  glm::dvec2 lower(1e30), upper(-1e30);
  for (int v : mesh.vertices()) lower = glm::min(lower, mesh.position(v)), upper = glm::max(upper, mesh.position(v));
  const float eye = sampleEyeHeight(dataset);
  const float y = float(0.5 * (lower.y + upper.y));
  const float length = std::min(float(upper.x - lower.x), 1.2f * float(frames) / 30.0f);
  const std::vector<CameraPose> poses =
      translatePath({float(lower.x) + 0.1f, y, eye}, {float(lower.x) + 0.1f + length, y, eye}, frames, 30.0f);
  const std::string size = "1280x720, " + std::to_string(frames) + " frames over " + formatNumber(length, 1) + " m, " +
                           std::to_string(mesh.vertexCount()) + " references of " + std::to_string(dataset.manifest().width) +
                           "x" + std::to_string(dataset.manifest().height);
  const auto loading = [](const Walk& result) {
    const std::string empty = result.empty > 0 ? ", " + std::to_string(result.empty) +
                                                     " of them with none of their references yet (nothing drawn, not timed)"
                                               : std::string();
    return std::to_string(result.incomplete) + " frames drawn with a reference still loading" + empty +
           "; working set " + std::to_string(result.cache.misses) + " misses, " + std::to_string(result.cache.hits) +
           " hits";
  };
  const auto addBudgetRow = [&](const std::string& name, const Walk& result, const std::string& more) {
    table.add({"viewer frame time walking, " + name + "frame budget " + formatNumber(kWalkFrameBudgetMilliseconds, 0) +
                   " ms (the viewer's default), median / p95",
               size, formatMedianAndP95(result.milliseconds),
               "mean scale " + formatNumber(result.meanScale, 2) +
                   " of each side while walking (full once the walker stops); " + loading(result) + more});
  };
  for (const SourceMesh sourceMesh : {SourceMesh::Grid, SourceMesh::Simplified}) {
    const std::string meshName = std::string(sourceMeshName(sourceMesh)) + " meshes, ";
    const auto meshCounts = [&](const Walk& result) {
      return sourceMesh == SourceMesh::Grid
                 ? std::string()
                 : "; meshes read from the store " + std::to_string(result.cache.meshesRead) + ", simplified " +
                       std::to_string(result.cache.meshesSimplified);
    };
    if (sourceMesh == SourceMesh::Simplified) {
      // The data set's mesh store as found (empty on a first visit): the
      // walk simplifies and stores what it meets; the walks after read it.
      const Walk first = walk(dataset, mesh, poses, sourceMesh, true);
      addBudgetRow(meshName + "store as found, ", first, meshCounts(first));
    }
    for (const bool holdBudget : {false, true}) {
      if (holdBudget && sourceMesh == SourceMesh::Simplified) {
        // The viewer's default, issue 15's figure: frame times on llvmpipe
        // move by several milliseconds from one walk to the next on the
        // same machine (docs/history/BENCHMARKS-2026-11.md, 2026-11-28), so several walks
        // are pooled and each one's figures shown.
        std::vector<Walk> walks;
        for (int k = 0; k < kPooledWalks; ++k) walks.push_back(walk(dataset, mesh, poses, sourceMesh, true));
        std::string each;
        for (const Walk& one : walks) each += (each.empty() ? "" : ", ") + formatMedianAndP95(one.milliseconds);
        const Walk all = pooled(walks);
        addBudgetRow(meshName + std::to_string(kPooledWalks) + " walks pooled, ", all,
                     meshCounts(all) + "; each walk's median / p95: " + each);
        continue;
      }
      const Walk result = walk(dataset, mesh, poses, sourceMesh, holdBudget);
      const std::string stored = meshCounts(result);
      if (holdBudget) {
        addBudgetRow(meshName, result, stored);
      } else {
        table.add({"viewer frame time walking, " + meshName + "full resolution, median / p95", size,
                   formatMedianAndP95(result.milliseconds),
                   "frames never wait for the disk: " + loading(result) + stored});
      }
    }
  }
  benchReferencePreparation(table, dataset, mesh);
  benchHolesFromNeighbours(table, dataset, mesh);
}

}  // namespace triwalk
