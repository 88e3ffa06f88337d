#include "app/bench/bench_groups.h"
#include "app/setup/walkthrough_setup.h"
#include "core/io/camera_path.h"
#include "render/walkthrough/frame_scale.h"
#include "render/walkthrough/walkthrough_renderer.h"

#include <algorithm>
#include <thread>

namespace triwalk {

namespace {

struct Walk {
  std::vector<double> milliseconds;
  double meanScale = 0.0;
  int incomplete = 0;  // frames drawn with a reference still loading
  PanoramaCache::Statistics cache;
};

// One walk from an empty working set, at full resolution or with the
// viewer's frame budget (render/walkthrough/frame_scale.h).
Walk walk(const Dataset& dataset, const ViewMesh& mesh, const std::vector<CameraPose>& poses, SourceMesh sourceMesh,
          bool holdBudget) {
  WarpOptions warpOptions;
  warpOptions.mesh = sourceMesh;
  PanoramaCache cache(dataset, warpOptions, size_t(1) << 30);
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
    const WalkthroughRenderer::Frame frame = renderer.render(camera, GpuWarpSettings{}, false);
    glFinish();
    const double elapsed = secondsSince(start);
    if (frame.available == 3) frameScale.record(scale, 1000.0 * elapsed);
    result.milliseconds.push_back(1000.0 * elapsed);
    result.meanScale += scale / double(poses.size());
    result.incomplete += frame.available < 3;
    // The walk advances at 30 frames a second at most, as a display would.
    if (elapsed < 1.0 / 30.0) std::this_thread::sleep_for(std::chrono::duration<double>(1.0 / 30.0 - elapsed));
  }
  result.cache = cache.statistics();
  return result;
}

}  // namespace

// The viewer's frame loop without the window: walking along a line at
// 1.2 m/s and 30 frames a second, panoramas from the working set that never
// blocks (a reference still loading is drawn without); with the exact grids
// and with simplified meshes, each at full resolution and with the frame
// budget the viewer walks with by default.
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
  for (const SourceMesh sourceMesh : {SourceMesh::Grid, SourceMesh::Simplified}) {
    const std::string meshName = std::string(sourceMeshName(sourceMesh)) + " meshes, ";
    for (const bool holdBudget : {false, true}) {
      const Walk result = walk(dataset, mesh, poses, sourceMesh, holdBudget);
      const std::string loading = std::to_string(result.incomplete) +
                                  " frames drawn with a reference still loading; working set " +
                                  std::to_string(result.cache.misses) + " misses, " + std::to_string(result.cache.hits) + " hits";
      if (holdBudget) {
        table.add({"viewer frame time walking, " + meshName + "frame budget " +
                       formatNumber(kWalkFrameBudgetMilliseconds, 0) + " ms (the viewer's default), median / p95",
                   size, formatMedianAndP95(result.milliseconds),
                   "mean scale " + formatNumber(result.meanScale, 2) +
                       " of each side while walking (full once the walker stops); " + loading});
      } else {
        table.add({"viewer frame time walking, " + meshName + "full resolution, median / p95", size,
                   formatMedianAndP95(result.milliseconds), "frames never wait for the disk: " + loading});
      }
    }
  }
}

}  // namespace triwalk
