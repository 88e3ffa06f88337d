#include "core/selection/tiled_selection.h"

#include "core/selection/reference_selection.h"
#include "core/selection/selection_refinement.h"
#include "core/support/errors.h"
#include "core/support/progress.h"
#include "core/synthesis/warp_layer_cache.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace triwalk {

// Cores of about 600 samples: a tile with its margin holds about 1,100 at
// the built-in capture's spacing, which the untiled decimation handles in
// a few minutes and well under 4 GiB, while below it the margins (a
// fixed width) would be most of every tile's work.
const int kTileCoreSamples = 600;

int defaultTileCount(int samples) { return std::max(1, int(std::lround(double(samples) / kTileCoreSamples))); }

namespace {

// The margin and the seam band in refinement radii (neighbourhoodRadius:
// about 1.4 sample spacings): the margin, about 1.9 m at the built-in
// spacing, holds a reference or two beyond the border of a core at the
// default quality target, so a reference near the border is chosen with
// its neighbours there; the band is half of it, the references whose
// triangles reach over the border.
constexpr double kMarginRadii = 4.0, kBandRadii = 2.0;

struct TileSettings {
  TriangleErrorSettings errors;
  SelectionSettings selection;
};

TileSettings tileSettings(const TilePlan& plan, const Dataset& dataset) {
  const JsonObject settings(plan.settings, "tile plan", "settings");
  TileSettings resolved;
  const std::optional<TriangleErrorSettings> errors = readSelectionErrors(settings, dataset);
  if (!errors) settings.fail("names no error settings");
  resolved.errors = *errors;
  resolved.selection.decimation = readDecimationOptions(settings);
  resolved.selection.decimation.maxError = settings.numberOr("max_error", 0.0);
  resolved.selection.refinement = readRefinementOptions(settings);
  return resolved;
}

std::vector<double> restricted(const std::vector<double>& values, std::span<const int> indices) {
  std::vector<double> result;
  result.reserve(indices.size());
  for (int i : indices) result.push_back(values[size_t(i)]);
  return result;
}

bool isAmong(std::span<const int> sorted, int sample) { return std::binary_search(sorted.begin(), sorted.end(), sample); }

// Sum and count of the dense triangle errors a tile owns: the triangles of
// its dense triangulation whose lowest sample is a member of its core, so
// each dense triangle is counted by one tile.
std::pair<double, size_t> measureTile(const Dataset& dataset, const Tile& tile, TriangleErrorSettings errorSettings) {
  const Dataset part = dataset.withSamples(tile.samples);
  errorSettings.layerCacheBytes = 0;  // each triangle is measured once
  DatasetTriangleErrors errors(part, errorSettings, LoadedViews::Samples, true);
  const ViewMesh dense = datasetMesh(part, {}, dataset.manifestPath().string());
  std::vector<Triangle> owned;
  for (const Triangle& t : dense.triangles()) {
    const int lowest = tile.samples[size_t(*std::min_element(t.begin(), t.end()))];
    if (isAmong(tile.core.members, lowest)) owned.push_back(t);
  }
  std::vector<double> values(owned.size());
  errors.computeErrors(owned, values);
  double sum = 0.0;
  for (double v : values) sum += v;
  return {sum, owned.size()};
}

}  // namespace

size_t tileLayerCacheBytes(int concurrent) {
  // A tile's share of what this machine may cache, and never more than
  // 1.5 GiB: a tile's peak memory is its views plus this, the same for
  // every tile of every capture.
  constexpr size_t kMostPerTile = size_t(3) << 29;
  return std::min(automaticLayerCacheBytes() / size_t(std::max(1, concurrent)), kMostPerTile);
}

TilePlan planTiles(const Dataset& dataset, const TilePlanRequest& request, bool quiet) {
  TilePlan plan;
  plan.datasetDirectory = std::filesystem::absolute(dataset.directory()).lexically_normal().string();
  plan.datasetSamples = dataset.sampleCount();
  plan.settings = request.settings;
  plan.request = {{"settings", request.settings}, {"tiles", request.tiles}};
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  const int count = request.tiles > 0 ? request.tiles : defaultTileCount(int(positions.size()));
  std::vector<TileCore> cores = splitIntoCores(positions, count);

  // The sample spacing, as the refinement measures it, from each core alone
  // (the whole capture's would cost n^2) and the median taken.
  std::vector<double> radii(cores.size());
  tbb::parallel_for(size_t(0), cores.size(), [&](size_t k) {
    std::vector<glm::dvec2> members;
    for (int i : cores[k].members) members.push_back(positions[size_t(i)]);
    radii[k] = neighbourhoodRadius(members);
  });
  std::vector<double> sorted = radii;
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
  const double radius = sorted[sorted.size() / 2];
  plan.margin = kMarginRadii * radius;
  plan.band = kBandRadii * radius;
  plan.tiles = tilesWithMargin(positions, std::move(cores), plan.margin);

  const JsonObject settings(plan.settings, "tile plan", "settings");
  if (!readRefinementOptions(settings).radius) plan.settings["refine_radius"] = radius;
  plan.target = settings.integerOr("target", 0);
  if (plan.target > 0) {
    for (const Tile& tile : plan.tiles) {
      const double share = double(plan.target) * double(tile.samples.size()) / double(positions.size());
      plan.tileTargets.push_back(std::max(3, int(std::ceil(share))));
    }
  }

  const double relative = settings.numberOr("relative_error", 0.0);
  if (relative > 0.0) {
    const TileSettings resolved = tileSettings(plan, dataset);
    std::vector<std::pair<double, size_t>> sums(plan.tiles.size());
    ProgressReporter progress("dense triangle errors, by tiles", plan.tiles.size(), quiet);
    tbb::task_arena arena(std::max(1, request.jobs));
    arena.execute([&] {
      tbb::parallel_for(size_t(0), plan.tiles.size(), size_t(1), [&](size_t k) {
        if (interruptRequested()) return;
        sums[k] = measureTile(dataset, plan.tiles[k], resolved.errors);
        progress.advance();
      });
    });
    progress.finish();
    throwIfInterrupted();
    double sum = 0.0;
    size_t triangles = 0;
    for (const auto& [tileSum, tileCount] : sums) sum += tileSum, triangles += tileCount;
    TRIWALK_CHECK(triangles > 0, "the dense triangulation has no triangles");
    plan.denseMeanError = sum / double(triangles);
    plan.settings["max_error"] = relative * plan.denseMeanError;
  }
  return plan;
}

TileOutcome runTile(const Dataset& dataset, const TilePlan& plan, int k, size_t layerCacheBytes, bool quiet) {
  TRIWALK_CHECK(k >= 0 && size_t(k) < plan.tiles.size(), "no such tile");
  const auto start = std::chrono::steady_clock::now();
  const Tile& tile = plan.tiles[size_t(k)];
  TileSettings settings = tileSettings(plan, dataset);
  settings.errors.layerCacheBytes = layerCacheBytes;
  SelectionSettings& selection = settings.selection;
  if (plan.target > 0) selection.decimation.targetSamples = plan.tileTargets[size_t(k)];
  // The whole capture's area shares: a sample at the margin's outer edge
  // stands for its own share, not for everything beyond the tile.
  selection.decimation.sampleWeights = restricted(selectionSampleWeights(dataset), tile.samples);

  const Dataset part = dataset.withSamples(tile.samples);
  DatasetTriangleErrors errors(part, settings.errors, LoadedViews::Samples, quiet);
  const SelectionRun run = selectReferences(part, errors, selection, quiet);

  TileOutcome outcome;
  for (int local : run.selection.samples) {
    const int sample = tile.samples[size_t(local)];
    if (isAmong(tile.core.members, sample)) outcome.references.push_back(sample);
  }
  std::sort(outcome.references.begin(), outcome.references.end());
  outcome.collapses = run.collapses;
  outcome.moves = run.refinement.moves.size();
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

StitchResult stitchTiles(const Dataset& dataset, const TilePlan& plan, const std::vector<TileOutcome>& outcomes,
                         size_t layerCacheBytes, bool quiet) {
  TRIWALK_CHECK(outcomes.size() == plan.tiles.size(), "one outcome per tile");
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  std::vector<char> isReference(positions.size(), 0);
  for (const TileOutcome& outcome : outcomes) {
    for (int r : outcome.references) isReference[size_t(r)] = 1;
  }
  StitchResult result;
  result.unionSamples = size_t(std::count(isReference.begin(), isReference.end(), 1));

  TileSettings settings = tileSettings(plan, dataset);
  settings.errors.layerCacheBytes = layerCacheBytes;
  const std::vector<double> weights = selectionSampleWeights(dataset);
  const WalkableRegion region = dataset.walkableRegion();
  std::vector<TileCore> cores;
  for (const Tile& tile : plan.tiles) cores.push_back(tile.core);
  std::vector<std::vector<int>> bands;
  size_t bandSamples = 0;
  for (const TileCore& core : cores) {
    bands.push_back(bandMembers(positions, core, plan.band, cores));
    bandSamples += bands.back().size();
  }

  // The seam pass, tile by tile in order, each seeing what the earlier ones
  // left: within the tile's views, the references of its band may collapse
  // and move; everything else is frozen.
  ProgressReporter progress("seam pass", plan.tiles.size(), quiet);
  for (size_t k = 0; k < plan.tiles.size(); ++k) {
    throwIfInterrupted();
    const Tile& tile = plan.tiles[k];
    std::vector<int> localReferences;
    std::vector<char> frozen(tile.samples.size(), 1);
    size_t freeReferences = 0;
    for (size_t local = 0; local < tile.samples.size(); ++local) {
      const int sample = tile.samples[local];
      if (isAmong(bands[k], sample)) frozen[local] = 0;
      if (isReference[size_t(sample)]) {
        localReferences.push_back(int(local));
        if (!frozen[local]) ++freeReferences;
      }
    }
    if (freeReferences == 0 || localReferences.size() < 4) {
      progress.advance();
      continue;
    }
    const Dataset part = dataset.withSamples(tile.samples);
    DatasetTriangleErrors errors(part, settings.errors, LoadedViews::Samples, true);
    CachingReconstructionErrors sampleErrors(errors);
    const ViewMesh mesh = datasetMesh(part, localReferences, dataset.manifestPath().string());

    DecimationOptions options = settings.selection.decimation;
    options.frozen = frozen;
    options.sampleWeights = restricted(weights, tile.samples);
    if (plan.target > 0) {
      // The references over the target, spread over the seams still to come
      // by their free references.
      const long total = long(std::count(isReference.begin(), isReference.end(), 1));
      size_t freeLeft = 0;
      for (size_t j = k; j < plan.tiles.size(); ++j) {
        for (int s : bands[j]) freeLeft += size_t(isReference[size_t(s)]);
      }
      const long excess = std::max(0L, total - long(plan.target));
      const long share = std::min<long>(long(freeReferences),
                                        long(std::ceil(double(excess) * double(freeReferences) / double(freeLeft))));
      options.targetSamples = std::max(3, mesh.vertexCount() - int(share));
      options.maxError = 0.0;
    }
    std::unique_ptr<EdgeCollapseDecimator> decimator =
        datasetDecimator(part, mesh.triangles(), DecimationErrors{&errors, &sampleErrors}, options);
    if (plan.target == 0 || options.targetSamples < mesh.vertexCount()) {
      if (decimator->run() == StopReason::Interrupted) throw Interrupted();
    }
    result.seamCollapses += decimator->log().size();

    RefinementOptions refinement = settings.selection.refinement;
    refinement.region = &region;
    refinement.sampleWeights = options.sampleWeights;
    refinement.frozen = frozen;
    refinement.maxExchanges = int(freeReferences);
    const RefinementResult refined = refineSelection(mesh.positions(), decimator->mesh().triangles(), sampleErrors,
                                                     refinement, nullptr);
    result.seamMoves += refined.moves.size();
    std::vector<char> kept(tile.samples.size(), 0);
    for (const Triangle& t : refined.triangles) {
      for (int v : t) kept[size_t(v)] = 1;
    }
    for (size_t local = 0; local < tile.samples.size(); ++local) {
      if (!frozen[local]) isReference[size_t(tile.samples[local])] = kept[local];
    }
    progress.advance();
  }
  progress.finish();

  std::vector<int> references;
  for (size_t i = 0; i < positions.size(); ++i) {
    if (isReference[i]) references.push_back(int(i));
  }
  const ViewMesh final = datasetMesh(dataset, references, dataset.manifestPath().string());
  Selection& selection = result.selection;
  selection.method = "tiled_edge_collapse";
  selection.samples = references;
  selection.triangles = final.triangles();
  selection.settings = plan.settings;
  selection.stopReason = stopReasonName(plan.target > 0 ? StopReason::TargetReached : StopReason::MaxError);
  selection.nextCost = std::numeric_limits<double>::infinity();
  return result;
}

}  // namespace triwalk
