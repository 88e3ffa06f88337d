#include "app/bench/bench_groups.h"
#include "core/image/image_compare.h"
#include "core/image/panorama_resample.h"
#include "core/synthesis/hole_fill.h"
#include "core/synthesis/reconstruction_error.h"
#include "core/synthesis/view_synthesis.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <memory>
#include <thread>

namespace triwalk {

namespace {

struct WarpRun {
  double seconds = 0.0;
  WarpTimings timings;
  uint64_t triangles = 0;
  double testedPerPixel = 0.0;  // pixel centres tested against a triangle, per destination pixel
};

WarpRun timeWarps(const WarpSource& source, const DestinationCamera& destination, int repetitions,
                  PanoramaRaster raster = PanoramaRaster::RowSpans,
                  LayerReliability reliability = LayerReliability::Computed) {
  WarpRun run;
  const auto warp = [&] {
    return warpToCamera(source, destination, WarpMethod::Mesh, reliability, raster);
  };
  warp();  // warm-up
  const auto start = BenchClock::now();
  for (int i = 0; i < repetitions; ++i) {
    const WarpLayer layer = warp();
    run.timings.projectSeconds += layer.timings.projectSeconds / repetitions;
    run.timings.rasterSeconds += layer.timings.rasterSeconds / repetitions;
    run.timings.resolveSeconds += layer.timings.resolveSeconds / repetitions;
    run.triangles = layer.trianglesRasterized;
    run.testedPerPixel = double(layer.pixelsTested) / double(layer.color.pixelCount());
  }
  run.seconds = secondsSince(start) / repetitions;
  return run;
}

std::string split(const WarpRun& run) {
  const double total = run.timings.projectSeconds + run.timings.rasterSeconds + run.timings.resolveSeconds;
  return "project " + formatNumber(100.0 * run.timings.projectSeconds / total, 0) + "%, raster " +
         formatNumber(100.0 * run.timings.rasterSeconds / total, 0) + "%, resolve " +
         formatNumber(100.0 * run.timings.resolveSeconds / total, 0) + "%; " +
         formatNumber(double(run.triangles) / run.timings.rasterSeconds / 1e6, 1) +
         " M triangles/s set up in raster, " + formatNumber(run.testedPerPixel, 1) +
         " pixel centres tested per destination pixel";
}

}  // namespace

void benchWarp(BenchTable& table, const BenchViews& views, int decimationWidth) {
  const Panorama& panorama = views.panoramas[0];
  const double megapixels = double(panorama.color.pixelCount()) / 1e6;
  const DestinationCamera destination = DestinationCamera::panorama(views.destination, 1024, 512);
  Rgb8Image gridFrame;
  for (const SourceMesh mesh : {SourceMesh::Grid, SourceMesh::Simplified}) {
    WarpOptions options;
    options.mesh = mesh;
    const auto prepareStart = BenchClock::now();
    const WarpSource source(panorama, views.positions[0], 0.0f, options);
    const double prepareSeconds = secondsSince(prepareStart);
    const std::string size = "1024x512 -> 1024x512, builtin scene, " + std::to_string(source.keptTriangleCount()) +
                             (mesh == SourceMesh::Grid ? " triangles kept of " + std::to_string(source.triangleCount())
                                                       : " triangles simplified at 0.25 px");
    const std::string name = mesh == SourceMesh::Grid ? "CPU warp" : "CPU warp, simplified source mesh";
    const WarpSource* pointers[] = {&source};
    const Rgb8Image frame = displayImage(synthesizeView(pointers, destination, {.warp = options, .blend = {}, .holes = HoleMode::Mark}).blended, HoleMode::Mark);
    std::string agreement;
    if (mesh == SourceMesh::Grid) {
      gridFrame = frame;
    } else {
      agreement = "; PSNR " + formatNumber(psnr(frame, gridFrame), 1) + " dB against the grid's warp";
    }
    const WarpRun all = timeWarps(source, destination, 5);
    table.add({name + ", all threads (" + std::to_string(std::thread::hardware_concurrency()) + ")", size,
               formatNumber(megapixels / all.seconds, 2) + " source Mpixel/s",
               formatNumber(1000.0 * all.seconds, 1) + " ms per warp; " + split(all) + "; source preparation " +
                   formatNumber(1000.0 * prepareSeconds, 1) + " ms" + agreement});
    // The plain scan of each triangle's whole range, which the row spans replace.
    const WarpRun scanned = timeWarps(source, destination, 5, PanoramaRaster::BoundingBox);
    table.add({name + ", every pixel of each triangle's range tested, all threads", size,
               formatNumber(megapixels / scanned.seconds, 2) + " source Mpixel/s",
               formatNumber(1000.0 * scanned.seconds, 1) + " ms per warp; " + split(scanned)});
    if (mesh != SourceMesh::Grid) continue;
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    const WarpRun one = timeWarps(source, destination, 3);
    table.add({name + ", 1 thread", size, formatNumber(megapixels / one.seconds, 2) + " source Mpixel/s",
               formatNumber(1000.0 * one.seconds, 1) + " ms per warp; " + split(one)});
  }

  // Triangle errors as decimation computes them: three sources warped to
  // the destination, blended and compared, many errors in parallel.
  const int factor = panorama.width() / decimationWidth;
  const ColorImage truth = toDisplayColors(downsamplePanorama(views.destinationPanorama, factor).color);
  const DestinationCamera smallDestination = DestinationCamera::panorama(views.destination, decimationWidth, decimationWidth / 2);
  for (const SourceMesh mesh : {SourceMesh::Grid, SourceMesh::Simplified}) {
    WarpOptions options;
    options.mesh = mesh;
    std::vector<std::unique_ptr<WarpSource>> small;
    std::vector<const WarpSource*> pointers;
    const auto prepareStart = BenchClock::now();
    for (size_t i = 0; i < 3; ++i) {
      small.push_back(std::make_unique<WarpSource>(downsamplePanorama(views.panoramas[i], factor), views.positions[i], 0.0f,
                                                   options));
      pointers.push_back(small.back().get());
    }
    const double prepareSeconds = secondsSince(prepareStart) / 3.0;
    if (mesh == SourceMesh::Simplified) {
      // One warp as the decimation warps it (its sources' size, no reliability).
      const WarpRun one = timeWarps(*small[0], smallDestination, 20, PanoramaRaster::RowSpans, LayerReliability::Omitted);
      table.add({"CPU warp at the decimation's width, simplified source mesh, all threads",
                 std::to_string(decimationWidth) + "x" + std::to_string(decimationWidth / 2) + " -> " +
                     std::to_string(decimationWidth) + "x" + std::to_string(decimationWidth / 2) + ", " +
                     std::to_string(small[0]->keptTriangleCount()) + " triangles, " +
                     std::to_string(small[0]->vertexCount()) + " vertices",
                 formatNumber(1000.0 * one.seconds, 2) + " ms per warp", split(one)});
    }
    const int errors = 64;
    const auto errorStart = BenchClock::now();
    tbb::parallel_for(0, errors, [&](int) {
      const SynthesizedView view = synthesizeView(pointers, smallDestination, SynthesisOptions{});
      reconstructionError(toDisplayColors(view.blended.color), view.blended.hole, truth, ErrorOptions{});
    });
    const double errorSeconds = secondsSince(errorStart);
    table.add({std::string("triangle errors (3 warps + blend + E), all threads, ") + sourceMeshName(mesh) + " source mesh",
               std::to_string(decimationWidth) + "x" + std::to_string(decimationWidth / 2) + ", " + std::to_string(errors) +
                   " errors",
               formatNumber(errors / errorSeconds, 1) + " errors/s",
               "the unit of work of decimation; source preparation " + formatNumber(1000.0 * prepareSeconds, 1) +
                   " ms each"});
  }
}

}  // namespace triwalk
