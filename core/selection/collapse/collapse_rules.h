#pragma once
// Which collapses are valid: the result must be a manifold planar
// triangulation covering the same region, or, where the boundary may
// shrink, a part of it.
//   - link condition: v1 and v2 share exactly the neighbours opposite their edge;
//   - two boundary vertices may only collapse along a boundary edge;
//   - every new triangle is counter-clockwise (exact predicate, never flat);
//   - fixed boundary (the paper's): the boundary never moves: a boundary
//     vertex may be removed only where it lies on the straight segment
//     between its boundary neighbours, and the placement must lie on that
//     segment (hull corners stay);
//   - shrinking boundary: the new triangles lie inside the removed ones; a
//     reference may leave a straight stretch of the boundary (see
//     staysInside), or leave with all its triangles (a removal), only
//     where the engine asks for these last resorts.
// Frozen samples (a tile's seam pass) never move: a frozen reference is
// never removed and a frozen free sample never becomes a reference.

#include "core/selection/collapse/collapse_mesh.h"
#include "core/selection/collapse/collapse_plan.h"

#include <vector>

namespace triwalk {

enum class BoundaryRule { Fixed, Shrinking };

class CollapseRules {
public:
  // frozen: by sample index, or empty for none.
  CollapseRules(const CollapseMesh& mesh, BoundaryRule boundary, std::vector<char> frozen);

  bool boundaryMayShrink() const { return boundary_ == BoundaryRule::Shrinking; }

  // The collapse of edge (a, b) into placement: its removed and added
  // triangles in plan, if valid. straightStretches: the last resort that
  // lets a reference leave a straight stretch of the boundary.
  bool planCollapse(int a, int b, int placement, PlacementKind kind, CollapsePlan& plan,
                    bool straightStretches = false) const;
  // Boundary reference `leaving` removed with all its triangles, keeping
  // its boundary neighbour `staying` (the plan's placement); `pieces` is
  // mesh.piecesWithout({}), taken once for all the candidates on one mesh.
  bool planRemoval(int leaving, int staying, int pieces, CollapsePlan& plan) const;

private:
  bool isFrozen(int sample) const { return !frozen_.empty() && frozen_[size_t(sample)]; }
  bool keepsFixedBoundary(int a, int b, int placement, const std::vector<int>& boundaryA,
                          const std::vector<int>& boundaryB) const;
  bool staysInside(int a, int b, const CollapsePlan& plan, bool straightStretches) const;
  bool keepsEveryVertex(int a, int b, const CollapsePlan& plan) const;

  const CollapseMesh& mesh_;
  BoundaryRule boundary_;
  std::vector<char> frozen_;
};

}  // namespace triwalk
