#pragma once
// Refinement of a decimated selection at a fixed sample count: move one
// reference at a time to a nearby free dense sample, or exchange a
// reference anywhere for a free sample anywhere, each time that lowers the
// mean reconstruction error over every dense sample that is not a
// reference (each reconstructed from the triangle around it in the
// Delaunay triangulation of the references, the nearest triangle outside
// the covered area, as the viewer and eval do), until nothing helps.
//
// Why: greedy collapses never revisit a choice. A collapse only ever
// shrinks the covered region and can never put a reference back where it
// took the last ones away: on a floor of rooms joined by doors, the
// collapses that were cheapest one at a time left whole rooms without a
// reference (docs/history/RESULTS-2026-11.md, "The selection suite"). The exchanges undo
// such choices wherever they are; the local moves then settle each
// reference among its neighbours. The dense samples measure what every
// step costs and gains directly.
//
//   objective(S) = mean over dense samples i not in S of E(i | triangle of S around i),
//                  weighted by each sample's share of the area
//   start from the Delaunay mesh of S (moves are judged on Delaunay meshes;
//   a decimated mesh, whose boundary shrank where that paid, can be better
//   than any of them and would stop every move)
//   local moves (every reference flagged)
//   while an exchange helps (at most maxExchanges):
//     loss(v) = objective(S - v) - objective(S)       for every reference v
//     gain(c) = objective(S + c) - objective(S)       for free samples c spread
//                                                      over the area (see exchangeCandidates)
//     for the pairs (v, c) of the lowest loss(v) + gain(c): objective(S - v + c), exactly
//     make the lowest if it is lower than now; local moves (the references
//     around v's old and c's new place flagged)
//   local moves: until no reference is flagged (or maxPasses passes):
//     for each flagged reference v, ascending:
//       try every free sample c within radius of v: S - v + c, Delaunay
//       keep the lowest objective if it is lower than now (ties: lower c)
//       flag the references around v's old and new place
//   keep the result if it is lower than the given mesh, else the given mesh
//   with no moves
//   screening (screenedShare > 0): each batch of candidates above is first
//   scored over a fixed random share of the dense samples, and only the best
//   few that beat the current selection there are scored over all of them
//   pricing (pricedSamples > 0, the default; not with screening): each
//   local move's change of the objective is first estimated, with its
//   standard error, from about pricedSamples of the samples whose triangle
//   it changes, and those that may beat the current selection (within two
//   standard errors) are priced again on `repricing` times as many, and
//   those that still may are scored over all of them (a candidate that
//   changes no more than a price takes is exact at once)
//
// Every move is logged like a collapse (kind "relocation", removed and
// added triangles; the first against the given mesh), so the collapse log
// replays through it. Errors of
// (dense sample, triangle) pairs are cached; deterministic for any thread
// count (only error batches run in parallel).

#include "core/geometry/planar_geometry.h"
#include "core/selection/edge_collapse_decimator.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace triwalk {

class ProgressReporter;

struct RefinementOptions {
  // Metres a reference may move per step; 0 disables refinement. Default:
  // neighbourhoodRadius of the samples, whatever their spacing.
  std::optional<double> radius;
  int maxPasses = 8;                  // of local moves, each time they run
  // Each sample's share of the area (empty: equal), for the mean; a sample
  // of weight 0 is not judged (a tile's margin: only its core is kept).
  std::vector<double> sampleWeights;
  // The walkable region: the references are triangulated keeping only
  // triangles inside it (see ViewMesh::delaunay); null or empty: all.
  const WalkableRegion* region = nullptr;
  // Exchanges between the local moves, at most this many; none: as many
  // as there are references (each may go once); 0: local moves only.
  std::optional<int> maxExchanges;
  // Screening: candidates are first ranked by the objective over this
  // share of the dense samples (a fixed random subset, see
  // samplePricingRank), and only the best few are scored over all of them;
  // 0: every candidate over all of them. A move is made only if its exact
  // objective is lower, so screening can miss a move, never make a worse one.
  double screenedShare = 0.0;
  // Pricing (when not screening): a local move is first priced against the
  // current selection on about this many of the samples whose triangle it
  // changes (a stratified random subset, as the decimator prices a
  // collapse, core/selection/sample_pricing.h), and scored over all of
  // them unless that estimate is two standard errors above the current
  // objective; one that changes no more is scored exactly at once. The
  // exchange search prices its single removals and insertions the same
  // way and scores exactly those that may rank among the lowest; the
  // exchanges it ranks from them are scored exactly. 0: every candidate
  // over all of them.
  int pricedSamples = 32;
  // Before a priced candidate that may beat the selection (or, in the
  // exchange search, rank among the lowest) is scored over every sample it
  // changes, it is priced again on this many times as many and ruled out
  // by the same two-standard-error test; 1: scored over all of them at once.
  int repricing = 4;
  // By sample index (empty: none): a frozen reference never moves or
  // leaves, a frozen free sample is never taken (a tiled selection's seam
  // pass refines only the band along a tile's border).
  std::vector<char> frozen = {};
};

struct RefinementResult {
  std::vector<Collapse> moves;      // kind Relocation: first moved to placement
  std::vector<Triangle> triangles;  // the final triangulation (sorted, canonical)
  double objectiveBefore = 0.0;     // of the starting triangles
  double objectiveAfter = 0.0;
  double radius = 0.0;               // the one used
  int exchanges = 0;                 // moves from anywhere to anywhere
  int passes = 0;                    // of local moves, in all
  uint64_t errorsComputed = 0;
  // Of errorsComputed, those the exchange searches computed (the rest are
  // the local moves' and the start's): the part that grows with the
  // insertion candidates, which a denser capture has more of.
  uint64_t exchangeSearchErrors = 0;
  uint64_t cacheHits = 0;
};

// How far a reference moves per step by default: to any of its eight
// nearest samples, i.e. 1.01 x the lower quartile over samples of the
// distance to their 8th nearest (on a square lattice, the diagonal
// neighbours; the quartile, so that the samples with neighbours all round
// set it, even in a region of corridors where most lie on an edge). An
// absolute radius would mean a different neighbourhood on every capture:
// 0.5 m reached the diagonals of the built-in scene's 0.35 m lattice, only
// two samples on a 0.31 x 0.54 m one, and none on a 1.46 m one.
double neighbourhoodRadius(std::span<const glm::dvec2> positions);

// The free samples an exchange may insert: spread over the area, no two
// nearer than 1.5 times the samples' typical spacing (the median distance
// to the nearest), lowest index first. The gain of an insertion varies
// smoothly with its place, so a spread subset finds where one is worth
// most at a third to a quarter of the cost, and the local moves place it
// exactly.
std::vector<int> exchangeCandidates(std::span<const glm::dvec2> positions, std::span<const int> references);

// current: the selection's triangles now (its vertices are the
// references). A move is kept only if it lowers the objective below that
// of the mesh in use, so the first one may also re-triangulate a decimated
// mesh. progress, if given, counts references examined; Ctrl-C throws
// Interrupted between batches.
RefinementResult refineSelection(std::span<const glm::dvec2> positions, const std::vector<Triangle>& current,
                                 ReconstructionErrorSource& errors, const RefinementOptions& options,
                                 ProgressReporter* progress = nullptr);

// Greedy insertion (issue 72), the mirror image of the collapse: from a
// start set of references, each step adds the free sample whose insertion
// lowers the objective above most, until there are count (or no insertion
// keeps a triangle in the region). Every free sample is scored at every
// step, priced as the exchange search prices its insertions (options'
// pricedSamples and repricing; 0: exactly) and scored exactly where it may
// be the lowest; ties go to the lower index. The insertions are in order,
// so the first k - start of them are the selection at count k.
struct InsertionResult {
  std::vector<int> inserted;        // in the order they joined
  std::vector<double> objectives;   // after each insertion
  std::vector<Triangle> triangles;  // the final triangulation
  double objectiveBefore = 0.0;     // of the start
  uint64_t errorsComputed = 0;
};
InsertionResult insertGreedily(std::span<const glm::dvec2> positions, std::span<const int> start, int count,
                               ReconstructionErrorSource& errors, const RefinementOptions& options,
                               ProgressReporter* progress = nullptr);

}  // namespace triwalk
