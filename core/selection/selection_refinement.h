#pragma once
// Refinement of a decimated selection at a fixed sample count: move one
// reference at a time to a nearby free dense sample when that lowers the
// mean reconstruction error over every dense sample that is not a
// reference (each reconstructed from the triangle around it in the
// Delaunay triangulation of the references, the nearest triangle outside
// the covered area, as the viewer and eval do), until no move helps.
//
// Why: decimation keeps the covered region (hull corners stay, boundary
// vertices only slide along it), so about half of a coarse selection sits
// on the edge of the walkable area, where a panorama serves half the area
// an interior one does. The dense samples measure what that costs, and
// what the move gains, directly; the hull may shrink when the nearest
// triangle reconstructs the outside well enough. docs/RESULTS.md has the
// measurements behind the radius and the objective.
//
//   objective(S) = mean over dense samples i not in S of E(i | triangle of S around i),
//                  weighted by each sample's share of the area
//   repeat until no reference is flagged (or maxPasses):
//     for each flagged reference v, ascending:
//       try every free sample c within radius of v: S - v + c, Delaunay
//       keep the lowest objective if it is lower than now (ties: lower c)
//       flag the references around v's old and new place
//
// Every move is logged like a collapse (kind "relocation", removed and
// added triangles), so the collapse log replays through it. Errors of
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
  int maxPasses = 8;
  std::vector<double> sampleWeights;  // each sample's share of the area (empty: equal), for the mean
  // The walkable region: the references are triangulated keeping only
  // triangles inside it (see ViewMesh::delaunay); null or empty: all.
  const WalkableRegion* region = nullptr;
};

struct RefinementResult {
  std::vector<Collapse> moves;      // kind Relocation: first moved to placement
  std::vector<Triangle> triangles;  // the final triangulation (sorted, canonical)
  double objectiveBefore = 0.0;     // of the starting triangles
  double objectiveAfter = 0.0;
  double radius = 0.0;               // the one used
  int passes = 0;
  uint64_t errorsComputed = 0;
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

// current: the selection's triangles now (its vertices are the
// references). A move is kept only if it lowers the objective below that
// of the mesh in use, so the first one may also re-triangulate a decimated
// mesh. progress, if given, counts references examined; Ctrl-C throws
// Interrupted between batches.
RefinementResult refineSelection(std::span<const glm::dvec2> positions, const std::vector<Triangle>& current,
                                 ReconstructionErrorSource& errors, const RefinementOptions& options,
                                 ProgressReporter* progress = nullptr);

}  // namespace triwalk
