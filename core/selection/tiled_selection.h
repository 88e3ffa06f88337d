#pragma once
// Tiled selection (docs/DESIGN.md, "Tiled selection"): a capture too large
// for one decimation is cut into tiles (core/selection/tile_partition.h),
// each tile decimated and refined on its own views, and the tiles
// stitched: the references of every core are kept, then a seam pass, a
// step a tile in rounds of tiles that do not reach each other, lets
// collapses and refinement change only the band along the core's
// borders, where two tiles' choices meet. Every tile and every
// seam step reads only its own views, so memory depends on the tile size
// and time grows linearly with the capture. The tiles are independent
// jobs: whatever runs them (threads, MPI ranks, a batch scheduler), the
// selection is the same, byte for byte.

#include "core/io/dataset.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection.h"
#include "core/selection/tile_partition.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace triwalk {

// Automatic tiles hold at most this many samples, core and margin, and
// decimate tiles by itself above it (see the definition for the measurement).
extern const size_t kTileSamples;

// What every tile runs with, resolved once for the whole capture.
struct TilePlan {
  // What was asked ({"settings": ..., "tiles": N}): a rerun asking the same
  // finds the plan and the tiles already run, and goes on from there.
  nlohmann::json request;
  // A hash of plan.json as read (readTilePlan): each tile's outcome names
  // the plan it was made for.
  std::string key;
  std::string datasetDirectory;  // absolute
  int datasetSamples = 0;
  // The selection file's settings (describeSelectionRecipe), with the
  // refinement radius and the absolute threshold resolved for the whole
  // capture: a relative threshold is measured against the whole capture's
  // dense mean (the tiles' own means would disagree).
  nlohmann::json settings;
  double denseMeanError = 0.0;  // 0: not measured (an absolute threshold or a target alone)
  double margin = 0.0;          // metres of samples around each core a tile also decimates
  double band = 0.0;            // metres from a core's border the seam pass may change
  int target = 0;               // total sample count asked for; 0: none
  std::vector<Tile> tiles;
  std::vector<int> tileTargets;  // per tile (with target): its share of the count
};

// What one tile chose: the references of its core (sample indices, sorted).
struct TileOutcome {
  std::vector<int> references;
  size_t collapses = 0, moves = 0;
  double seconds = 0.0;
};

struct TilePlanRequest {
  nlohmann::json settings;  // describeSelectionRecipe of the request (max_error, relative_error, target)
  int tiles = 0;            // 0: as many as keep every tile within kTileSamples
  int jobs = 1;             // tiles measured at once
};

// The margin of every tile (and the seam band's width), in metres, for a
// capture of `samples` whose refinement radius is `radius`: 4 radii, and
// two reference spacings where a target count (0: none) makes the
// references sparser than that.
double tileMargin(double radius, size_t samples, int target);

// Cuts the capture into tiles and resolves the settings; measures the dense
// mean by tiles (each loading only its views, `jobs` at a time) when the
// threshold is relative. Progress unless quiet; Ctrl-C throws Interrupted.
TilePlan planTiles(const Dataset& dataset, const TilePlanRequest& request, bool quiet);

// What each of a tile's samples is in its own selection (indices local to
// tile.samples): every one weighted by its share of the whole capture's
// area (captureWeights, by sample index); the core's counted toward a
// target, moved and judged by the refinement; the margin's the frozen
// context, neither counted nor judged.
void assignTileRoles(const Tile& tile, const std::vector<double>& captureWeights, SelectionSettings& selection);

// Decimates and refines tile k on its views alone; layerCacheBytes bounds
// its cache of warped layers.
TileOutcome runTile(const Dataset& dataset, const TilePlan& plan, int k, size_t layerCacheBytes, bool quiet);

struct StitchResult {
  Selection selection;  // method "tiled_edge_collapse", settings the plan's
  size_t tiles = 0;
  size_t unionSamples = 0;  // references of the cores before the seam pass
  size_t seamCollapses = 0, seamMoves = 0;
  size_t seamColours = 0;  // rounds of the seam pass (steps of one round run at once)
  size_t seamPasses = 0;   // passes after the first that took out some of what was still over the target
  size_t coreRemovals = 0;  // references the cores' own pass took out where the bands could not (empty bands)
  size_t isolatedRemovals = 0;  // references in no view triangle dropped to meet the target when no step could
  size_t pieceRemovals = 0;     // then references of the smallest pieces of the triangulation, the same way
};

// "the seam pass (2 rounds) made 3 collapses and 35 moves", and the passes
// after the first, the cores' pass and the references dropped when there
// were any.
std::string describeSeamPass(const StitchResult& result);

// How many references each step of a seam round takes out, with `excess`
// references over the target and free[i] references in step i's band
// (freeLeft: in the bands of this round and the rounds after it): the
// round's share of the excess by its free references, rounded up, split
// among its steps by largest remainder, none more than its band holds.
std::vector<int> roundRemovals(long excess, std::span<const long> free, long freeLeft);

// The seam pass's rounds: tiles coloured (greedily, in tile order) so that
// no two of a colour reach each other, i.e. neither's band holds a sample
// of the other's tile. bands[k]: the samples tile k's seam step may change.
std::vector<int> seamColours(const std::vector<Tile>& tiles, const std::vector<std::vector<int>>& bands,
                             size_t sampleCount);

// The union of the tiles' references, the seam pass (colour by colour, the
// steps of a colour up to `jobs` at a time), and the final triangulation
// (walls respected). outcomes: one per tile, in order. The selection does
// not depend on jobs.
StitchResult stitchTiles(const Dataset& dataset, const TilePlan& plan, const std::vector<TileOutcome>& outcomes,
                         int jobs, bool quiet);

// The layer cache each of `concurrent` tile runs in one process may use.
size_t tileLayerCacheBytes(int concurrent);

}  // namespace triwalk
