#include "core/selection/collapse/collapse_rules.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <set>

namespace triwalk {

namespace {

// Whether both outline edges at vertex x lie on the line through pu and
// pv: the outline runs straight through x there.
bool outlineRunsAlong(const std::vector<std::pair<int, int>>& outline, int x, const std::vector<glm::dvec2>& positions,
                      const glm::dvec2& pu, const glm::dvec2& pv) {
  int ends = 0;
  for (const auto& [from, to] : outline) {
    if (from != x && to != x) continue;
    if (orientation(pu, pv, positions[size_t(from == x ? to : from)]) != 0) return false;
    ++ends;
  }
  return ends == 2;
}

}  // namespace

CollapseRules::CollapseRules(const CollapseMesh& mesh, BoundaryRule boundary, std::vector<char> frozen)
    : mesh_(mesh), boundary_(boundary), frozen_(std::move(frozen)) {}

bool CollapseRules::planCollapse(int a, int b, int placement, PlacementKind kind, CollapsePlan& plan,
                                 bool straightStretches) const {
  if (isFrozen(placement) || (a != placement && isFrozen(a)) || (b != placement && isFrozen(b))) return false;
  const std::vector<int> shared = mesh_.edgeTriangles(a, b);
  if (shared.empty() || shared.size() > 2) return false;

  // Link condition: the common neighbours are exactly the opposite vertices.
  std::vector<int> opposite;
  for (int t : shared) {
    for (int v : mesh_.triangle(t)) {
      if (v != a && v != b) opposite.push_back(v);
    }
  }
  std::sort(opposite.begin(), opposite.end());
  const std::vector<int> na = mesh_.neighboursOf(a), nb = mesh_.neighboursOf(b);
  std::vector<int> common;
  std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
  if (common != opposite) return false;

  const std::vector<int> boundaryA = mesh_.boundaryNeighbours(a), boundaryB = mesh_.boundaryNeighbours(b);
  const bool onBoundaryA = !boundaryA.empty(), onBoundaryB = !boundaryB.empty();
  const bool boundaryEdge = shared.size() == 1;
  if (onBoundaryA && onBoundaryB && !boundaryEdge) return false;   // would pinch the mesh
  if (boundaryA.size() > 2 || boundaryB.size() > 2) return false;  // a vertex the boundary passes twice
  const bool boundaryMoves = (onBoundaryA && placement != a) || (onBoundaryB && placement != b);
  if (boundaryMoves && !boundaryMayShrink() && !keepsFixedBoundary(a, b, placement, boundaryA, boundaryB)) return false;

  // The updated triangles: every triangle of a or b but the edge's own,
  // with a and b replaced by the placement; all strictly counter-clockwise.
  plan.placement = placement;
  plan.kind = kind;
  plan.removed.clear();
  plan.added.clear();
  for (int vertex : {a, b}) {
    for (int t : mesh_.incident(vertex)) {
      if (std::find(plan.removed.begin(), plan.removed.end(), t) == plan.removed.end()) plan.removed.push_back(t);
    }
  }
  std::sort(plan.removed.begin(), plan.removed.end());
  for (int t : plan.removed) {
    if (std::find(shared.begin(), shared.end(), t) != shared.end()) continue;
    Triangle updated = mesh_.triangle(t);
    for (int& v : updated) {
      if (v == a || v == b) v = placement;
    }
    if (orientation(mesh_.position(updated[0]), mesh_.position(updated[1]), mesh_.position(updated[2])) <= 0) {
      return false;
    }
    plan.added.push_back(canonicalTriangle(updated));
  }
  // Without new triangles only an ear of the boundary goes (the edge's one
  // triangle), and only where the boundary may shrink.
  if (plan.added.empty() && !(boundaryMoves && boundaryMayShrink())) return false;
  // A canonical order makes sums over them independent of triangle ids,
  // i.e. of the history that led to this mesh.
  std::sort(plan.added.begin(), plan.added.end());
  std::vector<uint64_t> keys;
  for (const Triangle& t : plan.added) keys.push_back(triangleKey(t));
  std::sort(keys.begin(), keys.end());
  if (std::adjacent_find(keys.begin(), keys.end()) != keys.end()) return false;
  return !(boundaryMoves && boundaryMayShrink()) ||
         (staysInside(a, b, plan, straightStretches) && keepsEveryVertex(a, b, plan));
}

// The paper's rule (docs/DESIGN.md, "Selection"): the boundary never moves. A boundary vertex
// may be removed only where it lies on the straight segment between its
// boundary neighbours, and the placement must lie on that segment.
bool CollapseRules::keepsFixedBoundary(int a, int b, int placement, const std::vector<int>& boundaryA,
                                       const std::vector<int>& boundaryB) const {
  const bool onBoundaryA = !boundaryA.empty(), onBoundaryB = !boundaryB.empty();
  if (onBoundaryA != onBoundaryB) {
    const int boundaryVertex = onBoundaryA ? a : b;
    const std::vector<int>& chain = onBoundaryA ? boundaryA : boundaryB;
    return chain.size() == 2 && mesh_.onOpenSegment(boundaryVertex, chain[0], chain[1]) &&
           mesh_.onOpenSegment(placement, chain[0], chain[1]);
  }
  // Boundary chain outerA - a - b - outerB becomes outerA - p - outerB.
  if (boundaryA.size() != 2 || boundaryB.size() != 2) return false;
  const int outerA = boundaryA[0] == b ? boundaryA[1] : boundaryA[0];
  const int outerB = boundaryB[0] == a ? boundaryB[1] : boundaryB[0];
  if (outerA == outerB) return false;  // the mesh would lose its last area
  if (placement == a) return mesh_.onOpenSegment(b, a, outerB);
  if (placement == b) return mesh_.onOpenSegment(a, outerA, b);
  return mesh_.onOpenSegment(a, outerA, outerB) && mesh_.onOpenSegment(b, outerA, outerB) &&
         mesh_.onOpenSegment(placement, outerA, outerB);
}

// Where the boundary may shrink: the new triangles must lie inside the
// removed ones (the region the collapse covers only loses area, so no
// triangle can come to overlap the rest of the mesh or cross a wall the
// mesh respected). The removed triangles form a disk (link condition);
// every new edge must be an edge of its outline or a diagonal inside it:
// crossing no outline edge, passing through no outline vertex, with its
// midpoint inside a removed triangle. With straightStretches (only once
// no other collapse is valid, see the engine's last resorts) a new edge
// may also pass through a freed vertex whose two outline edges run along
// it: a reference leaves a straight stretch of the boundary, which loses
// no area.
bool CollapseRules::staysInside(int a, int b, const CollapsePlan& plan, bool straightStretches) const {
  const auto freed = [&](int vertex) {
    return straightStretches && (vertex == a || vertex == b) && vertex != plan.placement;
  };
  std::set<std::pair<int, int>> directed;
  for (int t : plan.removed) {
    const Triangle& tri = mesh_.triangle(t);
    for (int e = 0; e < 3; ++e) directed.insert({tri[size_t(e)], tri[size_t((e + 1) % 3)]});
  }
  std::vector<std::pair<int, int>> outline;
  for (const auto& [u, v] : directed) {
    if (!directed.count({v, u})) outline.emplace_back(u, v);
  }
  for (const Triangle& t : plan.added) {
    for (int e = 0; e < 3; ++e) {
      const int u = t[size_t(e)], v = t[size_t((e + 1) % 3)];
      if (directed.count({u, v}) || directed.count({v, u})) continue;  // an edge that was there
      const glm::dvec2 pu = mesh_.position(u), pv = mesh_.position(v);
      for (const auto& [x, y] : outline) {
        const glm::dvec2 px = mesh_.position(x), py = mesh_.position(y);
        if (x != u && x != v && orientation(pu, pv, px) == 0 && glm::dot(px - pu, px - pv) <= 0.0 &&
            !(freed(x) && outlineRunsAlong(outline, x, mesh_.positions(), pu, pv))) {
          return false;
        }
        if (x == u || x == v || y == u || y == v) continue;
        const int o1 = orientation(pu, pv, px), o2 = orientation(pu, pv, py);
        const int o3 = orientation(px, py, pu), o4 = orientation(px, py, pv);
        if (o1 * o2 < 0 && o3 * o4 < 0) return false;
      }
      const glm::dvec2 midpoint = 0.5 * (pu + pv);
      bool inside = false;
      for (int r : plan.removed) {
        inside |= distanceToTriangle(mesh_.positions(), mesh_.triangle(r), midpoint) == 0.0;
        if (inside) break;
      }
      if (!inside) return false;
    }
  }
  return true;
}

// No vertex but the two collapsed may lose its last triangle.
bool CollapseRules::keepsEveryVertex(int a, int b, const CollapsePlan& plan) const {
  for (int t : plan.removed) {
    for (int v : mesh_.triangle(t)) {
      if (v == a || v == b || v == plan.placement) continue;
      const bool inAdded = std::any_of(plan.added.begin(), plan.added.end(), [&](const Triangle& added) {
        return std::find(added.begin(), added.end(), v) != added.end();
      });
      const std::vector<int>& around = mesh_.incident(v);
      const bool keepsOther = std::any_of(around.begin(), around.end(), [&](int other) {
        return !std::binary_search(plan.removed.begin(), plan.removed.end(), other);
      });
      if (!inAdded && !keepsOther) return false;
    }
  }
  return plan.removed.size() < size_t(mesh_.triangleCount());
}

// A boundary reference leaves with all its triangles, none added: the
// covered area loses its fan, and the samples the fan served go to the
// best-ranked triangles left. Valid where every other vertex of the fan
// keeps a triangle and stays on the boundary once (no pinch), and the mesh
// falls into no more pieces than it had: on a ring of triangles (a loop of
// corridors) this cuts the ring open, after which its ends can collapse.
bool CollapseRules::planRemoval(int leaving, int staying, int pieces, CollapsePlan& plan) const {
  if (isFrozen(leaving)) return false;
  if (!boundaryMayShrink() || mesh_.edgeTriangles(leaving, staying).size() != 1) return false;
  if (mesh_.boundaryNeighbours(leaving).size() != 2) return false;
  plan.placement = staying;
  plan.kind = PlacementKind::Removal;
  plan.removed = mesh_.incident(leaving);
  plan.added.clear();
  std::sort(plan.removed.begin(), plan.removed.end());
  if (plan.removed.size() >= size_t(mesh_.triangleCount())) return false;
  for (int w : mesh_.neighboursOf(leaving)) {
    std::map<int, int> edgeUses;  // of w's edges, among its triangles left
    for (int t : mesh_.incident(w)) {
      if (std::binary_search(plan.removed.begin(), plan.removed.end(), t)) continue;
      for (int x : mesh_.triangle(t)) {
        if (x != w) ++edgeUses[x];
      }
    }
    const auto boundaryEdges =
        std::count_if(edgeUses.begin(), edgeUses.end(), [](const auto& use) { return use.second == 1; });
    if (edgeUses.empty() || boundaryEdges != 2) return false;
  }
  return mesh_.piecesWithout(plan.removed) <= pieces;
}

}  // namespace triwalk
