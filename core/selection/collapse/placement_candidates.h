#pragma once
// Where a collapsed edge's reference may go: the paper's three (either
// end, or the free dense sample nearest the midpoint) and, asked for,
// every free sample inside the triangles of either end (the one-ring).

#include "core/selection/collapse/collapse_mesh.h"

#include <limits>
#include <vector>

namespace triwalk {

struct PlacementCandidate {
  int sample = -1;
  PlacementKind kind = PlacementKind::First;
};

// The free sample nearest an edge's midpoint (the edge's own ends count as
// free): when it changes, the edge must be priced again.
struct NearestToMidpoint {
  int sample = -1;
  double distance = std::numeric_limits<double>::infinity();
};

// The candidates of edge (a, b), in the order ties are broken in; sets
// nearest.
std::vector<PlacementCandidate> placementCandidates(const CollapseMesh& mesh, int a, int b, bool oneRing,
                                                    NearestToMidpoint& nearest);

}  // namespace triwalk
