#include "app/bench/bench_groups.h"
#include "app/video/video_file.h"
#include "core/geometry/camera_path.h"
#include "render/walkthrough/gpu_warper.h"

#include <filesystem>
#include <memory>
#include <numeric>

namespace triwalk {

namespace {

// render --video and the viewer's export: the turn's frames, rendered
// first, then encoded alone, so that the row is the encoder's rate.
template <typename RenderAt>
void benchVideoEncoding(BenchTable& table, const std::vector<CameraPose>& poses, RenderAt& renderAt, GpuWarper& warper) {
  std::vector<Rgb8Image> frames;
  for (const CameraPose& pose : poses) {
    renderAt(pose, HoleMode::Fill, false);
    frames.push_back(warper.readPixels());
  }
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "triwalk-bench-video.mp4";
  const auto start = BenchClock::now();
  VideoWriter video(file, warper.width(), warper.height(), 30);
  for (const Rgb8Image& frame : frames) video.write(frame);
  video.commit();
  const double seconds = secondsSince(start);
  const double megabytes = double(std::filesystem::file_size(file)) / 1e6;
  std::filesystem::remove(file);
  table.add({"video encoding (render --video, the viewer's export), " + video.codecName(),
             std::to_string(warper.width()) + "x" + std::to_string(warper.height()) + ", " + std::to_string(frames.size()) +
                 " frames of the turn",
             formatNumber(double(frames.size()) / seconds, 1) + " frames/s",
             "encoding alone (frames rendered first); " + formatNumber(megabytes / (double(frames.size()) / 30.0) * 60.0, 0) +
                 " MB a minute at 30 frames/s"});
}

}  // namespace

void benchRender(BenchTable& table, const BenchViews& views, int frames) {
  GpuWarper warper(1280, 720);
  PinholeCamera camera;  // 1280x720, 60 degrees vertical
  camera.position = views.destination;
  // A full turn: every direction of the references is in view once.
  const std::vector<CameraPose> poses = rotatePath(views.destination, frames);
  const std::string size = "1280x720, 60 deg vertical, 3 references 1024x512, " + std::to_string(frames) + " frames of a turn";

  for (const SourceMesh mesh : {SourceMesh::Grid, SourceMesh::Simplified}) {
    WarpOptions options;
    options.mesh = mesh;
    const std::string meshName = std::string(sourceMeshName(mesh)) + " meshes";
    std::vector<std::unique_ptr<GpuPanorama>> panoramas;
    std::vector<const GpuPanorama*> references;
    double prepareSeconds = 0.0;
    for (size_t i = 0; i < 3; ++i) {
      const auto start = BenchClock::now();
      const WarpSource source(views.panoramas[i], views.positions[i], 0.0f, options);
      const PreparedPanorama prepared = preparePanorama(views.panoramas[i], 0.0f, source);
      prepareSeconds += secondsSince(start) / 3.0;
      panoramas.push_back(std::make_unique<GpuPanorama>(prepared));
      references.push_back(panoramas.back().get());
    }
    table.add({"GPU panorama preparation (" + meshName + ", the viewer's loader thread)", "1024x512",
               formatNumber(1000.0 * prepareSeconds, 0) + " ms",
               "stretch test, tiles" + std::string(mesh == SourceMesh::Simplified ? ", simplification (0.25 px)" : "") +
                   "; mean of the 3 references"});
    auto renderWith = [&](const CameraPose& pose, const GpuWarpSettings& settings, bool timePasses) {
      camera.yawDegrees = pose.yawDegrees;
      return warper.render(camera, references, settings, timePasses);
    };
    auto renderAt = [&](const CameraPose& pose, HoleMode holes, bool timePasses) {
      GpuWarpSettings settings;
      settings.holes = holes;
      return renderWith(pose, settings, timePasses);
    };
    renderAt(poses[0], HoleMode::Fill, true);  // warm-up: shader compilation

    // The frame as walked (holes filled), with holes marked, and the
    // viewer's trust overlay (T: the resolve colours by trust, no fill).
    GpuWarpSettings trust;
    trust.showTrust = true;
    for (const auto& [label, settings] : {std::pair{std::string("holes fill"), GpuWarpSettings{}},
                                          std::pair{std::string("holes mark"), GpuWarpSettings{BlendOptions{}, HoleMode::Mark}},
                                          std::pair{std::string("the viewer's trust overlay (T)"), trust}}) {
      std::vector<double> milliseconds;
      size_t triangles = 0, drawnTiles = 0, culledTiles = 0;
      for (const CameraPose& pose : poses) {
        glFinish();
        const auto start = BenchClock::now();
        const GpuFrameStatistics statistics = renderWith(pose, settings, false);
        glFinish();
        milliseconds.push_back(1000.0 * secondsSince(start));
        triangles += statistics.trianglesDrawn;
        drawnTiles += statistics.tilesDrawn;
        culledTiles += statistics.tilesCulled;
      }
      table.add({"GPU warp frame time, " + meshName + ", " + label + ", median / p95", size,
                 formatMedianAndP95(milliseconds),
                 formatNumber(double(triangles) / double(frames) / 1e6, 2) + " M triangles a frame after culling " +
                     formatNumber(100.0 * double(culledTiles) / double(drawnTiles + culledTiles), 0) + "% of the tiles"});
    }

    std::array<double, 3> layers{};
    double resolve = 0.0, fill = 0.0;
    for (const CameraPose& pose : poses) {
      const GpuFrameStatistics statistics = renderAt(pose, HoleMode::Fill, true);
      for (size_t k = 0; k < 3; ++k) layers[k] += statistics.layerMilliseconds[k] / double(frames);
      resolve += statistics.resolveMilliseconds / double(frames);
      fill += statistics.fillMilliseconds / double(frames);
    }
    if (mesh == SourceMesh::Simplified) benchVideoEncoding(table, poses, renderAt, warper);
    table.add({"GPU warp passes, " + meshName + " (mean, glFinish after each)", size,
               "layers " + formatNumber(layers[0], 1) + " + " + formatNumber(layers[1], 1) + " + " + formatNumber(layers[2], 1) +
                   " ms, resolve " + formatNumber(resolve, 1) + " ms, hole fill " + formatNumber(fill, 1) + " ms",
               "a layer: one reference's visible tiles drawn with a depth test; resolve: the epsilon blend, full screen; "
               "hole fill: the push-pull passes over all pyramid levels"});
  }
}

}  // namespace triwalk
