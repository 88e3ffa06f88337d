#include "core/selection/tiled_selection.h"

#include "core/selection/reference_selection.h"
#include "core/selection/selection_recipe.h"
#include "core/selection/selection_refinement.h"
#include "core/support/errors.h"
#include "core/support/progress.h"
#include "core/synthesis/warp_layer_cache.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

namespace triwalk {

// Tiles of at most 1,000 samples, core and margin. A tile's refinement
// costs more than linearly in its samples (each exchange searches all its
// references and free samples, and larger tiles make more exchanges): with
// cores of 600, the tiles of a 5,744-sample floor (up to 1,198 samples
// with margins on four sides) took 3.4x as long each as those of a
// 1,584-sample floor (up to 902). Bounding the tile, not the core, makes
// every tile of every capture cost about the same, so the total grows with
// the tile count, linearly in the capture. Smaller tiles are mostly
// margin (a fixed width in sample spacings) and seam: tiles of 700 were
// 11 to 18% faster but left the 1,940-sample floor's selection +4.9% +-
// 3.0% above the untiled one (docs/BENCHMARKS.md, "Tiled decimation").
const size_t kTileSamples = 1000;

namespace {

// The margin and the seam band in refinement radii (neighbourhoodRadius:
// about 1.4 sample spacings): the margin, about 1.9 m at the built-in
// spacing, holds a reference or two beyond the border of a core at the
// default quality target, so a reference near the border is chosen with
// its neighbours there. The band is as wide: each of two neighbouring
// tiles chose references up to a margin into the other's core, so the
// strip where their choices overlap is a margin wide on each side of the
// border. On the 1,940-sample floor at 256 references, a band of half the
// margin left the tiled selection +3.1% +- 2.4% above the untiled one at
// the probes, the whole margin +1.0% +- 2.1%.
constexpr double kMarginRadii = 4.0;

}  // namespace

double tileMargin(double radius, size_t samples, int target) {
  const double fixed = kMarginRadii * radius;
  if (target <= 0 || samples == 0) return fixed;
  // With a target count the references' spacing is known before any tile
  // runs: each stands for samples / target samples' area, and evenly
  // spread points with one per area A are sqrt(2 A / sqrt(3)) from their
  // neighbours; the samples' own spacing is radius / sqrt(2) (the eighth
  // neighbour of a grid is a diagonal one). A border reference's collapse
  // is decided with its one-ring, whose members are decided with theirs:
  // the margin holds two reference spacings so both rings beyond the
  // border are there. At a count of a fifth of the samples two spacings
  // are 3.4 radii, under the fixed margin; sparser selections (5% and 10%
  // of the samples: the suite's 4-tile rows lost 5.7% and 5.6% there,
  // 0.2% at 20%) get a margin that grows with their spacing.
  const double area = double(samples) / double(target) * (radius * radius / 2.0);
  const double referenceSpacing = std::sqrt(2.0 * area / std::sqrt(3.0));
  return std::max(fixed, 2.0 * referenceSpacing);
}

namespace {

// What a tile decimates with: the plan's recipe, to its absolute
// threshold (a relative one was measured on the whole capture when the
// plan was made) and, with a target, to the tile's share of it (set by
// the caller from the plan).
SelectionRecipe tileSettings(const TilePlan& plan, const Dataset& dataset) {
  SelectionRecipe recipe = readSelectionRecipe(JsonObject(plan.settings, "tile plan", "settings"), dataset);
  recipe.selection.relativeError = 0.0;
  recipe.selection.decimation.targetSamples = 0;
  return recipe;
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

  // The sample spacing, as the refinement measures it, from parts of the
  // capture of a tile's size (the whole capture's would cost n^2), the
  // median taken; the same whatever the tile count asked for.
  const std::vector<TileCore> parts = splitIntoCores(positions, 0.0, {.mostTileSamples = kTileSamples});
  std::vector<double> radii(parts.size());
  tbb::parallel_for(size_t(0), parts.size(), [&](size_t k) {
    std::vector<glm::dvec2> members;
    for (int i : parts[k].members) members.push_back(positions[size_t(i)]);
    radii[k] = neighbourhoodRadius(members);
  });
  std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(radii.size() / 2), radii.end());
  const double radius = radii[radii.size() / 2];
  const JsonObject settings(plan.settings, "tile plan", "settings");
  plan.target = settings.integerOr("target", 0);
  plan.margin = tileMargin(radius, positions.size(), plan.target);
  plan.band = plan.margin;
  const CoreSplitStop stop = request.tiles > 0 ? CoreSplitStop{.count = request.tiles}
                                                 : CoreSplitStop{.mostTileSamples = kTileSamples};
  plan.tiles = tilesWithMargin(positions, splitIntoCores(positions, plan.margin, stop), plan.margin);

  if (!readRefinementOptions(settings).radius) plan.settings["refine_radius"] = radius;
  if (plan.target > 0) {
    // Each tile's core its share of the samples and 5% more, counted over
    // the core alone (DecimationOptions::counted): the references gather
    // where the errors are, so a core's references vary by a few percent
    // around its share of the samples, and the seam pass can take out
    // references, never add them. (Counted over the whole tile, the
    // margin's references, dropped at the stitch, left the suite's scenes
    // in 4 tiles 5% to 22% short of the target.)
    constexpr double kTargetSurplus = 1.05;
    for (const Tile& tile : plan.tiles) {
      const double share = double(plan.target) * double(tile.core.members.size()) / double(positions.size());
      plan.tileTargets.push_back(std::max(3, int(std::ceil(kTargetSurplus * share))));
    }
  }

  const double relative = settings.numberOr("relative_error", 0.0);
  if (relative > 0.0) {
    const SelectionRecipe resolved = tileSettings(plan, dataset);
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

void assignTileRoles(const Tile& tile, const std::vector<double>& captureWeights, SelectionSettings& selection) {
  // The whole capture's area shares: a sample at the margin's outer edge
  // stands for its own share, not for everything beyond the tile.
  selection.decimation.sampleWeights = restricted(captureWeights, tile.samples);
  // The refinement moves only the core's references, among the core's
  // samples: the margin's references are dropped after this run, so moving
  // them would cost about as much again as the core (more than the core in
  // a tile inside the capture, margin on four sides) and change nothing
  // kept. They stay where the collapses left them, as the context the
  // core's references near the border are judged with; the seam pass
  // settles the border. And it judges the core's samples only: the
  // margin's frozen references serve a margin cut off at the tile's edge
  // badly whatever the core does (a strip of a room beyond a wall with no
  // triangle), and judged, that error decided whether the refinement was
  // kept at all (on the 1,940-sample floor tile 0 dropped all its moves,
  // leaving a corridor's two ends without references).
  selection.refinement.sampleWeights = selection.decimation.sampleWeights;
  selection.refinement.frozen.assign(tile.samples.size(), 0);
  selection.decimation.counted.assign(tile.samples.size(), 0);
  for (size_t local = 0; local < tile.samples.size(); ++local) {
    const bool inCore = isAmong(tile.core.members, tile.samples[local]);
    selection.refinement.frozen[local] = inCore ? 0 : 1;
    selection.decimation.counted[local] = inCore ? 1 : 0;  // the target is the core's
    if (!inCore) selection.refinement.sampleWeights[local] = 0.0;
  }
}

TileOutcome runTile(const Dataset& dataset, const TilePlan& plan, int k, size_t layerCacheBytes, bool quiet) {
  TRIWALK_CHECK(k >= 0 && size_t(k) < plan.tiles.size(), "no such tile");
  const auto start = std::chrono::steady_clock::now();
  const Tile& tile = plan.tiles[size_t(k)];
  SelectionRecipe settings = tileSettings(plan, dataset);
  settings.errors.layerCacheBytes = layerCacheBytes;
  SelectionSettings& selection = settings.selection;
  if (plan.target > 0) selection.decimation.targetSamples = plan.tileTargets[size_t(k)];
  assignTileRoles(tile, selectionSampleWeights(dataset), selection);

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

namespace {

// What one seam step decided: for each sample of its band (in band order),
// whether it is a reference afterwards.
struct SeamStep {
  std::vector<char> bandKept;
  size_t collapses = 0, moves = 0;
};

// The seam step of tile k over its views: the references of its band may
// collapse and move, everything else is frozen. It reads the references of
// the tile's samples only and changes those of its band only, which is
// what lets steps of tiles that do not reach each other run at once.
SeamStep runSeamStep(const Dataset& dataset, const TilePlan& plan, const SelectionRecipe& settings,
                     const std::vector<double>& weights, const WalkableRegion& region, size_t k,
                     std::span<const int> band, const std::vector<char>& isReference, int removals) {
  const Tile& tile = plan.tiles[k];
  SeamStep step;
  for (int s : band) step.bandKept.push_back(isReference[size_t(s)]);
  std::vector<int> localReferences;
  std::vector<char> frozen(tile.samples.size(), 1);
  for (size_t local = 0; local < tile.samples.size(); ++local) {
    const int sample = tile.samples[local];
    if (isAmong(band, sample)) frozen[local] = 0;
    if (isReference[size_t(sample)]) localReferences.push_back(int(local));
  }
  if (localReferences.size() < 4) return step;

  const Dataset part = dataset.withSamples(tile.samples);
  const ViewMesh mesh = datasetMesh(part, localReferences, dataset.manifestPath().string());
  // A reference in no triangle of the tile's own triangulation (its room
  // cut by the tile's edge) is no vertex of this mesh, so to the collapses
  // and moves it looks like a free sample: frozen, it is never taken as a
  // placement (which would count one reference for two) and never counted
  // among those the step may take out.
  size_t freeReferences = 0;
  for (int local : localReferences) {
    if (!isAmong(mesh.vertices(), local)) frozen[size_t(local)] = 1;
    if (!frozen[size_t(local)]) ++freeReferences;
  }
  if (freeReferences == 0) return step;

  DatasetTriangleErrors errors(part, settings.errors, LoadedViews::Samples, true);
  CachingReconstructionErrors sampleErrors(errors);
  DecimationOptions options = settings.selection.decimation;
  options.frozen = frozen;
  options.sampleWeights = restricted(weights, tile.samples);
  // The step takes out what it was given and no more, with or without a
  // target (stitchTiles says why). A step given nothing to take out (every
  // step without a target) only moves: building the decimator would price
  // every edge of the tile for collapses it never makes.
  options.targetSamples = std::max(3, mesh.vertexCount() - std::min(removals, int(freeReferences)));
  options.maxError = 0.0;
  std::vector<Triangle> triangles = mesh.triangles();
  std::vector<Collapse> collapses;
  if (options.targetSamples < mesh.vertexCount()) {
    const std::unique_ptr<EdgeCollapseDecimator> decimator =
        datasetDecimator(part, mesh.triangles(), DecimationErrors{&errors, &sampleErrors}, options);
    if (decimator->run() == StopReason::Interrupted) throw Interrupted();
    triangles = decimator->mesh().triangles();
    collapses = decimator->log();
  }
  step.collapses = collapses.size();

  RefinementOptions refinement = settings.selection.refinement;
  refinement.region = &region;
  refinement.sampleWeights = options.sampleWeights;
  refinement.frozen = frozen;
  refinement.maxExchanges = int(freeReferences);
  const RefinementResult refined =
      refineSelection(mesh.positions(), triangles, sampleErrors, refinement, nullptr);
  step.moves = refined.moves.size();
  // What the collapses and moves did, replayed on the references the step
  // started from: a reference in no triangle of the tile's own
  // triangulation (its room cut by the tile's edge, say) is one of the
  // whole capture's all the same, and stays.
  std::vector<char> kept(tile.samples.size(), 0);
  for (int local : localReferences) kept[size_t(local)] = 1;
  const auto replay = [&](const Collapse& change) {
    kept[size_t(change.first)] = 0;
    if (change.kind != PlacementKind::Relocation) kept[size_t(change.second)] = 0;
    kept[size_t(change.placement)] = 1;
  };
  for (const Collapse& collapse : collapses) replay(collapse);
  for (const Collapse& move : refined.moves) replay(move);
  for (size_t i = 0; i < band.size(); ++i) {
    const auto local = std::lower_bound(tile.samples.begin(), tile.samples.end(), band[i]) - tile.samples.begin();
    step.bandKept[i] = kept[size_t(local)];
  }
  return step;
}

}  // namespace

std::string describeSeamPass(const StitchResult& result) {
  std::string text = "the seam pass (" + std::to_string(result.seamColours) + " rounds) made " +
                     std::to_string(result.seamCollapses) + " collapses and " + std::to_string(result.seamMoves) + " moves";
  if (result.seamPasses > 0) {
    text += ", " + std::to_string(result.seamPasses) + (result.seamPasses == 1 ? " pass" : " passes") +
            " more toward the target";
  }
  if (result.coreRemovals > 0) {
    text += "; the cores' pass took out " + std::to_string(result.coreRemovals) + " the bands could not";
  }
  if (result.isolatedRemovals > 0) {
    text += "; " + std::to_string(result.isolatedRemovals) + " in no view triangle dropped";
  }
  if (result.pieceRemovals > 0) {
    text += "; " + std::to_string(result.pieceRemovals) + " dropped from the smallest pieces of the triangulation";
  }
  return text;
}

namespace {

// The triangles of the edge-connected piece of mesh with the fewest
// triangles (of equal ones, the piece of the lowest triangle index).
std::vector<int> smallestPiece(const ViewMesh& mesh) {
  std::vector<int> pieceOf(size_t(mesh.triangleCount()), -1);
  std::vector<int> smallest;
  for (int seed = 0; seed < mesh.triangleCount(); ++seed) {
    if (pieceOf[size_t(seed)] >= 0) continue;
    std::vector<int> piece = {seed};
    pieceOf[size_t(seed)] = seed;
    for (size_t next = 0; next < piece.size(); ++next) {
      for (int edge = 0; edge < 3; ++edge) {
        const int across = mesh.neighbour(piece[next], edge);
        if (across >= 0 && pieceOf[size_t(across)] < 0) pieceOf[size_t(across)] = seed, piece.push_back(across);
      }
    }
    if (smallest.empty() || piece.size() < smallest.size()) smallest = std::move(piece);
  }
  return smallest;
}

// Of the candidates (samples among references), the one nearest another
// reference (ties: the lowest index).
int nearestToAnother(std::span<const int> candidates, std::span<const int> references,
                     const std::vector<glm::dvec2>& positions) {
  std::pair<double, int> best = {std::numeric_limits<double>::infinity(), -1};
  for (int c : candidates) {
    for (int other : references) {
      if (other != c) best = std::min(best, {glm::length(positions[size_t(other)] - positions[size_t(c)]), c});
    }
  }
  return best.second;
}

}  // namespace

std::vector<int> roundRemovals(long excess, std::span<const long> free, long freeLeft) {
  std::vector<int> removals(free.size(), 0);
  const long freeHere = std::accumulate(free.begin(), free.end(), 0L);
  if (excess <= 0 || freeHere <= 0 || freeLeft <= 0) return removals;
  // The round's share of the excess, rounded up so that the last rounds
  // are not left more than their bands can give, then handed out by
  // largest remainder (ties to the earlier step): the round removes its
  // share exactly, where each step's share rounded up would remove more
  // than the excess. A share is at most the round's free references, so
  // no step is given more than its band holds.
  const long share = std::min({excess, freeHere, (excess * freeHere + freeLeft - 1) / freeLeft});
  std::vector<std::pair<long, size_t>> remainders;  // (minus the remainder of share * free_i / freeHere, step)
  long given = 0;
  for (size_t i = 0; i < free.size(); ++i) {
    removals[i] = int(share * free[i] / freeHere);
    given += removals[i];
    remainders.push_back({-(share * free[i] % freeHere), i});
  }
  std::sort(remainders.begin(), remainders.end());
  for (size_t j = 0; j < remainders.size() && given < share; ++j, ++given) ++removals[remainders[j].second];
  return removals;
}

std::vector<int> seamColours(const std::vector<Tile>& tiles, const std::vector<std::vector<int>>& bands,
                             size_t sampleCount) {
  // Tiles j and k reach each other when the band one step changes holds a
  // sample the other step reads (its tile's samples).
  std::vector<std::vector<int>> tilesOfSample(sampleCount);
  for (size_t k = 0; k < tiles.size(); ++k) {
    for (int s : tiles[k].samples) tilesOfSample[size_t(s)].push_back(int(k));
  }
  std::vector<std::vector<int>> reaches(tiles.size());
  for (size_t j = 0; j < tiles.size(); ++j) {
    for (int s : bands[j]) {
      for (int k : tilesOfSample[size_t(s)]) {
        if (size_t(k) == j) continue;
        reaches[j].push_back(k);
        reaches[size_t(k)].push_back(int(j));
      }
    }
  }
  // A band holds many samples of the same neighbour: each pair once.
  for (std::vector<int>& neighbours : reaches) {
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  }
  // Greedy in tile order: each tile the lowest colour none of the earlier
  // tiles it reaches has. A tile with n neighbours needs at most colour n,
  // so the colours taken are marked in an array of n + 1 (not of every tile).
  std::vector<int> colours(tiles.size(), -1);
  std::vector<char> taken;
  for (size_t k = 0; k < tiles.size(); ++k) {
    taken.assign(reaches[k].size() + 1, 0);
    for (int other : reaches[k]) {
      const int colour = colours[size_t(other)];
      if (colour >= 0 && size_t(colour) < taken.size()) taken[size_t(colour)] = 1;
    }
    colours[k] = int(std::find(taken.begin(), taken.end(), 0) - taken.begin());
  }
  return colours;
}

StitchResult stitchTiles(const Dataset& dataset, const TilePlan& plan, const std::vector<TileOutcome>& outcomes,
                         int jobs, bool quiet) {
  TRIWALK_CHECK(outcomes.size() == plan.tiles.size(), "one outcome per tile");
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  std::vector<char> isReference(positions.size(), 0);
  for (const TileOutcome& outcome : outcomes) {
    for (int r : outcome.references) isReference[size_t(r)] = 1;
  }
  StitchResult result;
  result.unionSamples = size_t(std::count(isReference.begin(), isReference.end(), 1));
  // Without a target the stitched selection keeps as many references as
  // the cores did: each core was decimated to the threshold measured on
  // the whole capture, and their union holds about what one decimation
  // keeps (238 against 239 on the 1,940-sample floor, 80 against 85 on the
  // tests' floor). A seam pass collapsing its bands to the threshold again
  // took out more (217 and 54 were left), and on that floor the probe
  // error rose with it (+16.3% +- 5.0% over one decimation's, against
  // +13.6% +- 4.9% keeping the count). So the seam pass moves the bands'
  // references and takes out only a target's surplus.
  const long target = plan.target > 0 ? long(plan.target) : long(result.unionSamples);

  const SelectionRecipe settings = [&] {
    SelectionRecipe resolved = tileSettings(plan, dataset);
    resolved.errors.layerCacheBytes = tileLayerCacheBytes(std::max(1, jobs));
    return resolved;
  }();
  const std::vector<double> weights = selectionSampleWeights(dataset);
  const WalkableRegion region = dataset.walkableRegion();
  std::vector<TileCore> cores;
  for (const Tile& tile : plan.tiles) cores.push_back(tile.core);
  std::vector<std::vector<int>> bands;
  for (const TileCore& core : cores) bands.push_back(bandMembers(positions, core, plan.band, cores));
  const std::vector<int> colours = seamColours(plan.tiles, bands, positions.size());
  result.seamColours = size_t(*std::max_element(colours.begin(), colours.end()) + 1);

  // The seam pass, colour by colour: the steps of one colour do not reach
  // each other, so they run at once and each sees what the earlier colours
  // left; the selection is the same whatever runs them.
  tbb::task_arena arena(std::max(1, jobs));
  const auto referenceCount = [&] { return long(std::count(isReference.begin(), isReference.end(), 1)); };
  const auto runRounds = [&](const std::vector<std::vector<int>>& changing, const std::vector<int>& colourOf,
                             ProgressReporter& progress, bool onlyRemoving) {
    const auto freeReferences = [&](size_t k) {
      long count = 0;
      for (int s : changing[k]) count += isReference[size_t(s)];
      return count;
    };
    const int rounds = *std::max_element(colourOf.begin(), colourOf.end()) + 1;
    for (int colour = 0; colour < rounds; ++colour) {
      throwIfInterrupted();
      std::vector<size_t> round;
      for (size_t k = 0; k < plan.tiles.size(); ++k) {
        if (colourOf[k] == colour) round.push_back(k);
      }
      // The references over the target are taken out here, spread over the
      // steps still to come by the free references they may change.
      std::vector<long> free;
      for (size_t k : round) free.push_back(freeReferences(k));
      long freeLeft = 0;
      for (size_t k = 0; k < plan.tiles.size(); ++k) {
        if (colourOf[k] >= colour) freeLeft += freeReferences(k);
      }
      std::vector<int> removals = roundRemovals(std::max(0L, referenceCount() - target), free, freeLeft);
      if (onlyRemoving) {
        std::vector<size_t> removing;
        std::vector<int> theirRemovals;
        for (size_t i = 0; i < round.size(); ++i) {
          if (removals[i] > 0) removing.push_back(round[i]), theirRemovals.push_back(removals[i]);
        }
        round = std::move(removing);
        removals = std::move(theirRemovals);
      }
      std::vector<SeamStep> steps(round.size());
      arena.execute([&] {
        tbb::parallel_for(size_t(0), round.size(), size_t(1), [&](size_t i) {
          if (interruptRequested()) return;
          steps[i] = runSeamStep(dataset, plan, settings, weights, region, round[i], changing[round[i]], isReference,
                                 removals[i]);
          progress.advance();
        });
      });
      throwIfInterrupted();
      for (size_t i = 0; i < round.size(); ++i) {
        const std::vector<int>& members = changing[round[i]];
        for (size_t b = 0; b < members.size(); ++b) isReference[size_t(members[b])] = steps[i].bandKept[b];
        result.seamCollapses += steps[i].collapses;
        result.seamMoves += steps[i].moves;
      }
    }
  };
  {
    ProgressReporter progress("seam pass, " + std::to_string(result.seamColours) + " rounds", plan.tiles.size(), quiet);
    runRounds(bands, colours, progress, false);
    progress.finish();
  }
  // A step takes out fewer than it was given where its band's references
  // cannot all collapse (a tile whose triangulation there is too thin):
  // what is still over the target is handed again to the steps that can,
  // pass after pass while a pass takes any out.
  const auto passesToTarget = [&](const std::vector<std::vector<int>>& changing, const std::vector<int>& colourOf,
                                  const std::string& what) {
    size_t passes = 0;
    while (referenceCount() > target) {
      const long before = referenceCount();
      ProgressReporter progress(what + ", " + std::to_string(before - target) + " over the target", 0, quiet);
      runRounds(changing, colourOf, progress, true);
      progress.finish();
      if (referenceCount() == before) break;
      ++passes;
    }
    return passes;
  };
  result.seamPasses = passesToTarget(bands, colours, "seam pass again");
  // Where the bands cannot give what is over the target (a tile whose
  // core meets no other, such as a building of its own, has an empty band
  // and kept its share of the surplus), the cores themselves give it: the
  // same steps with every reference of the core free, in rounds of tiles
  // that do not reach each other's cores.
  if (referenceCount() > target) {
    std::vector<std::vector<int>> wholeCores;
    for (const Tile& tile : plan.tiles) wholeCores.push_back(tile.core.members);
    const long before = referenceCount();
    passesToTarget(wholeCores, seamColours(plan.tiles, wholeCores, positions.size()), "the cores' pass");
    result.coreRemovals = size_t(before - referenceCount());
  }

  const auto keptReferences = [&] {
    std::vector<int> kept;
    for (size_t i = 0; i < positions.size(); ++i) {
      if (isReference[i]) kept.push_back(int(i));
    }
    return kept;
  };
  std::vector<int> references = keptReferences();
  ViewMesh final = datasetMesh(dataset, references, dataset.manifestPath().string());
  // What no step can take out is references in no triangle of their
  // tile's triangulation (a room cut off with fewer than three). Those in
  // no triangle of the whole serve no view triangle (the untiled
  // decimation drops them the same way), so they go first, the one
  // nearest another reference first, until the count is met. Below one
  // reference a room's worth the pieces of the triangulation can end as
  // lone triangles no step can shrink (the tests' floor of 3 rooms at 12
  // references: 5 triangles, 15 references): then the smallest piece
  // gives its reference nearest another, whose samples go to the
  // best-ranked triangle left, as the untiled decimation's last resort
  // removes a reference with its fan.
  while (referenceCount() > target) {
    std::vector<int> candidates;
    for (int r : references) {
      if (!isAmong(final.vertices(), r)) candidates.push_back(r);
    }
    const bool isolated = !candidates.empty();
    if (!isolated) {
      const std::vector<int> piece = smallestPiece(final);
      for (const int t : piece) candidates.insert(candidates.end(), final.triangles()[size_t(t)].begin(),
                                                  final.triangles()[size_t(t)].end());
    }
    const int leaving = nearestToAnother(candidates, references, positions);
    isReference[size_t(leaving)] = 0;
    (isolated ? result.isolatedRemovals : result.pieceRemovals) += 1;
    references = keptReferences();
    final = datasetMesh(dataset, references, dataset.manifestPath().string());
  }
  result.tiles = plan.tiles.size();
  Selection& selection = result.selection;
  selection.method = "tiled_edge_collapse";
  selection.samples = references;
  selection.triangles = final.triangles();
  selection.settings = plan.settings;
  selection.settings["tiles"] = plan.tiles.size();
  selection.stopReason = stopReasonName(plan.target > 0 ? StopReason::TargetReached : StopReason::MaxError);
  selection.nextCost = std::numeric_limits<double>::infinity();
  return result;
}

}  // namespace triwalk
