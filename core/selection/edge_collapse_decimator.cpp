#include "core/selection/edge_collapse_decimator.h"

#include "core/support/errors.h"
#include "core/support/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <unordered_set>

namespace triwalk {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

uint64_t tripleKey(const Triangle& triangle) {
  const Triangle t = sortedTriangle(triangle);
  return (uint64_t(t[0]) << 42) | (uint64_t(t[1]) << 21) | uint64_t(t[2]);
}

bool hasVertex(const Triangle& t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

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

const char* placementName(PlacementKind kind) {
  switch (kind) {
    case PlacementKind::First: return "first";
    case PlacementKind::Second: return "second";
    case PlacementKind::Midpoint: return "midpoint";
    case PlacementKind::OneRing: return "one-ring";
    case PlacementKind::Relocation: return "relocation";
    case PlacementKind::Removal:
      return "removal";
  }
  return "?";
}

const char* collapseCostName(CollapseCost cost) {
  return cost == CollapseCost::ServedSamples ? "served-samples" : "centroid";
}

CollapseCost parseCollapseCost(const std::string& name) {
  if (name == "served-samples") return CollapseCost::ServedSamples;
  if (name == "centroid") return CollapseCost::Centroid;
  throw InputError("cost", "unknown cost '" + name + "' (use served-samples or centroid)");
}

const char* recostingName(bool lazyRecosting) { return lazyRecosting ? "lazy" : "eager"; }

bool parseLazyRecosting(const std::string& name) {
  if (name == "lazy" || name == "eager") return name == "lazy";
  throw InputError("recosting", "unknown recosting '" + name + "' (use lazy or eager)");
}

const char* stopReasonName(StopReason reason) {
  switch (reason) {
    case StopReason::None: return "not stopped";
    case StopReason::MaxError: return "every collapse left would exceed the error threshold";
    case StopReason::TargetReached: return "reached the target sample count";
    case StopReason::NoValidCollapse: return "no valid collapse is left";
    case StopReason::Interrupted: return "interrupted";
  }
  return "?";
}

EdgeCollapseDecimator::EdgeCollapseDecimator(const ViewMesh& mesh, DecimationErrors errors, DecimationOptions options,
                                             ProgressReporter* costing)
    : positions_(mesh.positions()), triangles_(mesh.triangles()), alive_(mesh.triangles().size(), 1),
      incident_(mesh.positions().size()), isVertex_(mesh.positions().size(), 0), errors_(errors), options_(options),
      region_(mesh.region()) {
  TRIWALK_CHECK(options.cost == CollapseCost::Centroid ? errors.triangles != nullptr : errors.samples != nullptr,
                "the decimator needs the error source of its cost");
  TRIWALK_CHECK(options.sampleWeights.empty() || options.sampleWeights.size() == mesh.positions().size(),
                "one weight per sample");
  TRIWALK_CHECK(options.frozen.empty() || options.frozen.size() == mesh.positions().size(), "one frozen flag per sample");
  TRIWALK_CHECK(options.counted.empty() || options.counted.size() == mesh.positions().size(), "one counted flag per sample");
  for (size_t t = 0; t < triangles_.size(); ++t) {
    for (int v : triangles_[t]) incident_[size_t(v)].push_back(int(t));
  }
  for (int v : mesh.vertices()) isVertex_[size_t(v)] = 1;
  vertexCount_ = mesh.vertexCount();
  for (int v : mesh.vertices()) countedCount_ += counts(v);
  if (region_ && !region_->convex()) sight_.assign(positions_.size() * positions_.size(), -1);
  if (options_.cost == CollapseCost::ServedSamples) serveInitialSamples(mesh, costing);
  std::set<Edge> edges;
  for (const Triangle& t : triangles_) {
    for (int e = 0; e < 3; ++e) {
      const int a = t[size_t(e)], b = t[size_t((e + 1) % 3)];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  costEdges(std::vector<Edge>(edges.begin(), edges.end()), costing);
}

int EdgeCollapseDecimator::triangleCount() const { return int(std::count(alive_.begin(), alive_.end(), char(1))); }

ViewMesh EdgeCollapseDecimator::mesh() const {
  std::vector<Triangle> triangles;
  for (size_t t = 0; t < triangles_.size(); ++t) {
    if (alive_[t]) triangles.push_back(canonicalTriangle(triangles_[t]));
  }
  std::sort(triangles.begin(), triangles.end());
  return ViewMesh(positions_, std::move(triangles), region_);
}

// ------------------------------------------------------------ topology --

std::vector<int> EdgeCollapseDecimator::neighboursOf(int vertex) const {
  std::vector<int> neighbours;
  for (int t : incident_[size_t(vertex)]) {
    for (int v : triangles_[size_t(t)]) {
      if (v != vertex) neighbours.push_back(v);
    }
  }
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  return neighbours;
}

std::vector<int> EdgeCollapseDecimator::edgeTriangles(int a, int b) const {
  std::vector<int> shared;
  for (int t : incident_[size_t(a)]) {
    if (hasVertex(triangles_[size_t(t)], b)) shared.push_back(t);
  }
  return shared;
}

std::vector<int> EdgeCollapseDecimator::boundaryNeighbours(int vertex) const {
  std::vector<int> result;
  for (int w : neighboursOf(vertex)) {
    if (edgeTriangles(vertex, w).size() == 1) result.push_back(w);
  }
  return result;
}

// Whether a sample lies on the open segment between two others (exact).
bool EdgeCollapseDecimator::onOpenSegment(int sample, int from, int to) const {
  const glm::dvec2 p = positions_[size_t(sample)], a = positions_[size_t(from)], b = positions_[size_t(to)];
  if (orientation(a, b, p) != 0) return false;
  const double along = glm::dot(p - a, b - a);
  return along > 0.0 && along < glm::dot(b - a, b - a);
}

// ------------------------------------------------------------- validity --

bool EdgeCollapseDecimator::simulate(int a, int b, int placement, PlacementKind kind, Plan& plan,
                                     bool straightStretches) const {
  if (isFrozen(placement) || (a != placement && isFrozen(a)) || (b != placement && isFrozen(b))) return false;
  const std::vector<int> shared = edgeTriangles(a, b);
  if (shared.empty() || shared.size() > 2) return false;

  // Link condition: the common neighbours are exactly the opposite vertices.
  std::vector<int> opposite;
  for (int t : shared) {
    for (int v : triangles_[size_t(t)]) {
      if (v != a && v != b) opposite.push_back(v);
    }
  }
  std::sort(opposite.begin(), opposite.end());
  const std::vector<int> na = neighboursOf(a), nb = neighboursOf(b);
  std::vector<int> common;
  std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
  if (common != opposite) return false;

  const std::vector<int> boundaryA = boundaryNeighbours(a), boundaryB = boundaryNeighbours(b);
  const bool onBoundaryA = !boundaryA.empty(), onBoundaryB = !boundaryB.empty();
  const bool boundaryEdge = shared.size() == 1;
  if (onBoundaryA && onBoundaryB && !boundaryEdge) return false;  // would pinch the mesh
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
    for (int t : incident_[size_t(vertex)]) {
      if (std::find(plan.removed.begin(), plan.removed.end(), t) == plan.removed.end()) plan.removed.push_back(t);
    }
  }
  std::sort(plan.removed.begin(), plan.removed.end());
  for (int t : plan.removed) {
    if (std::find(shared.begin(), shared.end(), t) != shared.end()) continue;
    Triangle updated = triangles_[size_t(t)];
    for (int& v : updated) {
      if (v == a || v == b) v = placement;
    }
    if (orientation(positions_[size_t(updated[0])], positions_[size_t(updated[1])], positions_[size_t(updated[2])]) <= 0) {
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
  for (const Triangle& t : plan.added) keys.push_back(tripleKey(t));
  std::sort(keys.begin(), keys.end());
  if (std::adjacent_find(keys.begin(), keys.end()) != keys.end()) return false;
  if (boundaryMoves && boundaryMayShrink() &&
      !(staysInside(a, b, plan, straightStretches) && keepsEveryVertex(a, b, plan))) {
    return false;
  }
  if (options_.cost == CollapseCost::ServedSamples) assignServedSamples(a, b, plan);
  return true;
}

// The paper's rule (docs/DESIGN.md, "Selection"): the boundary never moves. A boundary vertex
// may be removed only where it lies on the straight segment between its
// boundary neighbours, and the placement must lie on that segment.
bool EdgeCollapseDecimator::keepsFixedBoundary(int a, int b, int placement, const std::vector<int>& boundaryA,
                                               const std::vector<int>& boundaryB) const {
  const bool onBoundaryA = !boundaryA.empty(), onBoundaryB = !boundaryB.empty();
  if (onBoundaryA != onBoundaryB) {
    const int boundaryVertex = onBoundaryA ? a : b;
    const std::vector<int>& chain = onBoundaryA ? boundaryA : boundaryB;
    return chain.size() == 2 && onOpenSegment(boundaryVertex, chain[0], chain[1]) &&
           onOpenSegment(placement, chain[0], chain[1]);
  }
  // Boundary chain outerA - a - b - outerB becomes outerA - p - outerB.
  if (boundaryA.size() != 2 || boundaryB.size() != 2) return false;
  const int outerA = boundaryA[0] == b ? boundaryA[1] : boundaryA[0];
  const int outerB = boundaryB[0] == a ? boundaryB[1] : boundaryB[0];
  if (outerA == outerB) return false;  // the mesh would lose its last area
  if (placement == a) return onOpenSegment(b, a, outerB);
  if (placement == b) return onOpenSegment(a, outerA, b);
  return onOpenSegment(a, outerA, outerB) && onOpenSegment(b, outerA, outerB) && onOpenSegment(placement, outerA, outerB);
}

// Where the boundary may shrink: the new triangles must lie inside the
// removed ones (the region the collapse covers only loses area, so no
// triangle can come to overlap the rest of the mesh or cross a wall the
// mesh respected). The removed triangles form a disk (link condition);
// every new edge must be an edge of its outline or a diagonal inside it:
// crossing no outline edge, passing through no outline vertex, with its
// midpoint inside a removed triangle. With straightStretches (only once
// no other collapse is valid, see peekValid) a new edge may also pass
// through a freed vertex whose two outline edges run along it: a
// reference leaves a straight stretch of the boundary, which loses no
// area.
bool EdgeCollapseDecimator::staysInside(int a, int b, const Plan& plan, bool straightStretches) const {
  const auto freed = [&](int vertex) {
    return straightStretches && (vertex == a || vertex == b) && vertex != plan.placement;
  };
  std::set<std::pair<int, int>> directed;
  for (int t : plan.removed) {
    const Triangle& tri = triangles_[size_t(t)];
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
      const glm::dvec2 pu = positions_[size_t(u)], pv = positions_[size_t(v)];
      for (const auto& [x, y] : outline) {
        const glm::dvec2 px = positions_[size_t(x)], py = positions_[size_t(y)];
        if (x != u && x != v && orientation(pu, pv, px) == 0 && glm::dot(px - pu, px - pv) <= 0.0 &&
            !(freed(x) && outlineRunsAlong(outline, x, positions_, pu, pv))) {
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
        const Triangle& tri = triangles_[size_t(r)];
        inside |= distanceToTriangle(positions_, tri, midpoint) == 0.0;
        if (inside) break;
      }
      if (!inside) return false;
    }
  }
  return true;
}

// No vertex but the two collapsed may lose its last triangle.
bool EdgeCollapseDecimator::keepsEveryVertex(int a, int b, const Plan& plan) const {
  for (int t : plan.removed) {
    for (int v : triangles_[size_t(t)]) {
      if (v == a || v == b || v == plan.placement) continue;
      const bool inAdded = std::any_of(plan.added.begin(), plan.added.end(), [&](const Triangle& added) {
        return std::find(added.begin(), added.end(), v) != added.end();
      });
      const bool keepsOther = std::any_of(incident_[size_t(v)].begin(), incident_[size_t(v)].end(), [&](int other) {
        return !std::binary_search(plan.removed.begin(), plan.removed.end(), other);
      });
      if (!inAdded && !keepsOther) return false;
    }
  }
  return plan.removed.size() < size_t(triangleCount());
}

// A boundary reference leaves with all its triangles, none added: the
// covered area loses its fan, and the samples the fan served go to the
// best-ranked triangles left. Valid where every other vertex of the fan
// keeps a triangle and stays on the boundary once (no pinch), and the mesh
// falls into no more pieces than it had: on a ring of triangles (a loop of
// corridors) this cuts the ring open, after which its ends can collapse.
bool EdgeCollapseDecimator::simulateRemoval(int leaving, int staying, int pieces, Plan& plan) const {
  if (isFrozen(leaving)) return false;
  if (!boundaryMayShrink() || edgeTriangles(leaving, staying).size() != 1) return false;
  if (boundaryNeighbours(leaving).size() != 2) return false;
  plan.placement = staying;
  plan.kind = PlacementKind::Removal;
  plan.removed = incident_[size_t(leaving)];
  plan.added.clear();
  std::sort(plan.removed.begin(), plan.removed.end());
  if (plan.removed.size() >= size_t(triangleCount())) return false;
  for (int w : neighboursOf(leaving)) {
    std::map<int, int> edgeUses;  // of w's edges, among its triangles left
    for (int t : incident_[size_t(w)]) {
      if (std::binary_search(plan.removed.begin(), plan.removed.end(), t)) continue;
      for (int x : triangles_[size_t(t)]) {
        if (x != w) ++edgeUses[x];
      }
    }
    const auto boundaryEdges =
        std::count_if(edgeUses.begin(), edgeUses.end(), [](const auto& use) { return use.second == 1; });
    if (edgeUses.empty() || boundaryEdges != 2) return false;
  }
  if (piecesWithout(plan.removed) > pieces) return false;
  if (options_.cost == CollapseCost::ServedSamples) assignServedSamples(leaving, staying, plan);
  return true;
}

int EdgeCollapseDecimator::piecesWithout(const std::vector<int>& removed) const {
  std::vector<char> seen(triangles_.size(), 0);
  for (int t : removed) seen[size_t(t)] = 1;
  int pieces = 0;
  for (size_t start = 0; start < triangles_.size(); ++start) {
    if (!alive_[start] || seen[start]) continue;
    ++pieces;
    std::vector<int> stack = {int(start)};
    seen[start] = 1;
    while (!stack.empty()) {
      const Triangle tri = triangles_[size_t(stack.back())];
      stack.pop_back();
      for (int e = 0; e < 3; ++e) {
        for (int t : edgeTriangles(tri[size_t(e)], tri[size_t((e + 1) % 3)])) {
          if (!seen[size_t(t)]) seen[size_t(t)] = 1, stack.push_back(t);
        }
      }
    }
  }
  return pieces;
}

// The samples the changed triangles will serve, and where each goes.
// Every sample is served by the triangle around it, or, outside the mesh
// (where the boundary shrank), by the best-ranked triangle (the nearest
// whose references see it, else the nearest), as eval and the viewer serve
// a position. Those are: the samples the removed triangles served, the
// freed vertices (not the placement, which becomes a reference), and
// samples outside the mesh that a new triangle now serves better (ties
// broken by the rank's vertex triple, as eval does).
void EdgeCollapseDecimator::assignServedSamples(int a, int b, Plan& plan) const {
  plan.served.clear();
  plan.servedBy.clear();
  for (int t : plan.removed) plan.served.insert(plan.served.end(), served_[size_t(t)].begin(), served_[size_t(t)].end());
  for (int freed : {a, b}) {
    if (freed != plan.placement) plan.served.push_back(freed);
  }
  auto bestAdded = [&](int sample, ServingRank& rank) {
    int home = -1;
    rank = {true, kInfinity, {}};
    for (size_t k = 0; k < plan.added.size() && rank.distance > 0.0; ++k) {
      const ServingRank r = servingRank(plan.added[k], sample);
      if (r < rank) rank = r, home = int(k);
    }
    return home;
  };
  for (int sample : outside_) {
    if (std::binary_search(plan.removed.begin(), plan.removed.end(), home_[size_t(sample)])) continue;  // listed above
    ServingRank rank;
    bestAdded(sample, rank);
    if (rank < homeRank_[size_t(sample)]) plan.served.push_back(sample);
  }
  plan.served.erase(std::remove(plan.served.begin(), plan.served.end(), plan.placement), plan.served.end());
  std::sort(plan.served.begin(), plan.served.end());
  plan.servedRank.clear();
  for (int sample : plan.served) {
    ServingRank rank;
    int home = bestAdded(sample, rank);
    if (rank.distance > 0.0) {
      // Outside the new triangles: an existing triangle may serve it better.
      for (int t = 0; t < int(triangles_.size()); ++t) {
        if (!alive_[size_t(t)] || std::binary_search(plan.removed.begin(), plan.removed.end(), t)) continue;
        const ServingRank r = servingRank(triangles_[size_t(t)], sample);
        if (r < rank) rank = r, home = -1 - t;
      }
    }
    plan.servedBy.push_back(home);
    plan.servedRank.push_back(rank);
  }
  choosePricedSamples(a, b, plan);
}

// Which served samples price the collapse, and how much each stands for:
// all of them, or, past pricedSamples, the freed vertices and, from the
// others, a share of each new serving triangle's samples (its share of the
// others, at least one): those of lowest fixed rank, each standing for
// its triangle's weight over theirs. Stratified by triangle because a
// sample's error depends mostly on the triangle serving it. The rank is
// the same for every plan, so the subsets of overlapping plans overlap
// (their errors are shared through the cache), and a late collapse, whose
// triangles serve hundreds of samples, costs what an early one does.
void EdgeCollapseDecimator::choosePricedSamples(int a, int b, Plan& plan) const {
  // The vertices the collapse frees are always priced; the others by a
  // stratified subset, by the triangle that serves them after it.
  plan.priced.clear();
  std::vector<int> others, strata, indices;
  for (size_t i = 0; i < plan.served.size(); ++i) {
    const int sample = plan.served[i];
    if (sample == a || sample == b) {
      plan.priced.push_back({int(i), 1.0});
    } else {
      others.push_back(sample);
      strata.push_back(plan.servedBy[i]);
      indices.push_back(int(i));
    }
  }
  for (const PricedSample& other :
       stratifiedPricing(others, strata, size_t(options_.pricedSamples), [this](int s) { return weightOf(s); })) {
    plan.priced.push_back({indices[size_t(other.index)], other.scale});
  }
  std::sort(plan.priced.begin(), plan.priced.end());
}

SampleReconstruction EdgeCollapseDecimator::servedRequest(const Plan& plan, size_t i) const {
  return {sortedTriangle(servingTriangle(plan, i)), plan.served[i]};
}

std::vector<SampleReconstruction> EdgeCollapseDecimator::pricedRequests(const Plan& plan) const {
  std::vector<SampleReconstruction> requests;
  for (const PricedSample& priced : plan.priced) requests.push_back(servedRequest(plan, size_t(priced.index)));
  return requests;
}

std::vector<SampleReconstruction> EdgeCollapseDecimator::servedRequests(const Plan& plan) const {
  std::vector<SampleReconstruction> requests;
  for (size_t i = 0; i < plan.served.size(); ++i) requests.push_back(servedRequest(plan, i));
  return requests;
}

std::vector<std::pair<int, PlacementKind>> EdgeCollapseDecimator::candidates(int a, int b, EdgeState& state) const {
  std::vector<std::pair<int, PlacementKind>> result = {{a, PlacementKind::First}, {b, PlacementKind::Second}};
  const glm::dvec2 midpoint = 0.5 * (positions_[size_t(a)] + positions_[size_t(b)]);
  state.midpointSample = -1;
  state.midpointDistance = kInfinity;
  for (int s = 0; s < int(positions_.size()); ++s) {
    if (isVertex_[size_t(s)] && s != a && s != b) continue;
    const double d = glm::length(positions_[size_t(s)] - midpoint);
    if (d < state.midpointDistance) state.midpointDistance = d, state.midpointSample = s;
  }
  if (state.midpointSample != a && state.midpointSample != b) result.push_back({state.midpointSample, PlacementKind::Midpoint});

  if (options_.oneRingCandidates) {
    std::vector<int> ring = incident_[size_t(a)];
    ring.insert(ring.end(), incident_[size_t(b)].begin(), incident_[size_t(b)].end());
    for (int s = 0; s < int(positions_.size()); ++s) {
      if (isVertex_[size_t(s)] || s == state.midpointSample) continue;
      for (int t : ring) {
        const Triangle& tri = triangles_[size_t(t)];
        bool inside = true;
        for (int e = 0; e < 3 && inside; ++e) {
          inside = orientation(positions_[size_t(tri[size_t(e)])], positions_[size_t(tri[size_t((e + 1) % 3)])],
                               positions_[size_t(s)]) >= 0;
        }
        if (inside) {
          result.push_back({s, PlacementKind::OneRing});
          break;
        }
      }
    }
  }
  return result;
}

// --------------------------------------------------------------- costs --

void EdgeCollapseDecimator::ensureErrors(const std::vector<Triangle>& triangles, ProgressReporter* progress) {
  std::vector<Triangle> missing;
  std::set<uint64_t> queued;
  for (const Triangle& t : triangles) {
    const uint64_t key = tripleKey(t);
    if (cache_.count(key) || !queued.insert(key).second) {
      ++statistics_.cacheHits;
      continue;
    }
    missing.push_back(t);
  }
  if (missing.empty()) return;
  // Progress is shown for the first costing, thousands of errors.
  const std::vector<double> computed = computeInChunks(
      std::span<const Triangle>(missing), progress, [&](std::span<const Triangle> batch, std::span<double> batchErrors) {
        errors_.triangles->computeErrors(batch, batchErrors);
      });
  for (size_t i = 0; i < missing.size(); ++i) cache_[tripleKey(missing[i])] = computed[i];
  statistics_.errorsComputed += missing.size();
}

void EdgeCollapseDecimator::ensureSampleErrors(const std::vector<SampleReconstruction>& requests, ProgressReporter* progress) {
  std::vector<SampleReconstruction> missing;
  std::unordered_set<SampleKey, SampleKeyHash> queued;
  for (const SampleReconstruction& request : requests) {
    const SampleKey key{tripleKey(request.references), request.destination};
    if (sampleCache_.count(key) || !queued.insert(key).second) {
      ++statistics_.cacheHits;
      continue;
    }
    missing.push_back(request);
  }
  if (missing.empty()) return;
  const std::vector<double> computed = computeInChunks(
      std::span<const SampleReconstruction>(missing), progress,
      [&](std::span<const SampleReconstruction> batch, std::span<double> batchErrors) {
        errors_.samples->computeReconstructionErrors(batch, batchErrors);
      });
  for (size_t i = 0; i < missing.size(); ++i) {
    sampleCache_[SampleKey{tripleKey(missing[i].references), missing[i].destination}] = computed[i];
  }
  statistics_.errorsComputed += missing.size();
}

double EdgeCollapseDecimator::sampleError(const Triangle& triangle, int sample) const {
  return sampleCache_.at(SampleKey{tripleKey(triangle), sample});
}

// Every sample that is not a vertex is served by the triangle around it
// (outside the mesh, when it is not the dense one, the best-ranked one).
void EdgeCollapseDecimator::serveInitialSamples(const ViewMesh& mesh, ProgressReporter* progress) {
  home_.assign(positions_.size(), -1);
  homeError_.assign(positions_.size(), 0.0);
  homeRank_.assign(positions_.size(), ServingRank{});
  served_.assign(triangles_.size(), {});
  std::vector<SampleReconstruction> requests;
  int hint = -1;
  for (int s = 0; s < int(positions_.size()); ++s) {
    if (isVertex_[size_t(s)]) continue;
    hint = mesh.locate(positions_[size_t(s)], hint);
    home_[size_t(s)] = hint;
    homeRank_[size_t(s)] = servingRank(triangles_[size_t(hint)], s);
    if (homeRank_[size_t(s)].distance > 0.0) outside_.insert(s);
    served_[size_t(hint)].push_back(s);
    requests.push_back({sortedTriangle(triangles_[size_t(hint)]), s});
  }
  ensureSampleErrors(requests, progress);
  for (const SampleReconstruction& request : requests) {
    homeError_[size_t(request.destination)] = sampleError(request.references, request.destination);
  }
}

double EdgeCollapseDecimator::weightOf(int sample) const {
  return options_.sampleWeights.empty() ? 1.0 : options_.sampleWeights[size_t(sample)];
}

double EdgeCollapseDecimator::servedSampleMeanError() const {
  double sum = 0.0, weightSum = 0.0;
  for (size_t s = 0; s < home_.size(); ++s) {
    if (home_[s] < 0) continue;
    sum += weightOf(int(s)) * homeError_[s];
    weightSum += weightOf(int(s));
  }
  return weightSum > 0.0 ? sum / weightSum : 0.0;
}

// The centroid cost of a collapse: the mean error of the updated triangles
// (paper Fig. 4), weighted by area unless asked otherwise, since a
// triangle serves the part of the walkthrough space it covers.
double EdgeCollapseDecimator::meanError(const std::vector<Triangle>& triangles) {
  double sum = 0.0, weightSum = 0.0;
  for (const Triangle& t : triangles) {
    const glm::dvec2 a = positions_[size_t(t[0])], b = positions_[size_t(t[1])], c = positions_[size_t(t[2])];
    const double weight = options_.areaWeightedCost ? 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) : 1.0;
    sum += weight * cache_.at(tripleKey(t));
    weightSum += weight;
  }
  return sum / weightSum;
}

double EdgeCollapseDecimator::triangleError(const Triangle& triangle) {
  TRIWALK_CHECK(errors_.triangles != nullptr, "triangle errors need a triangle error source");
  ensureErrors({triangle});
  return cache_.at(tripleKey(triangle));
}

const Triangle& EdgeCollapseDecimator::servingTriangle(const Plan& plan, size_t i) const {
  const int by = plan.servedBy[i];
  return by >= 0 ? plan.added[size_t(by)] : triangles_[size_t(-1 - by)];
}

// As ViewMesh::locate ranks triangles, from the samples' own positions.
ServingRank EdgeCollapseDecimator::servingRank(const Triangle& triangle, int sample) const {
  return rankTriangle(triangle, distanceToTriangle(positions_, triangle, positions_[size_t(sample)]),
                      [&](int v) { return sight_.empty() || seesEachOther(v, sample); });
}

bool EdgeCollapseDecimator::seesEachOther(int reference, int sample) const {
  int8_t& known = sight_[size_t(reference) * positions_.size() + size_t(sample)];
  if (known < 0) known = region_->lineOfSight(positions_[size_t(reference)], positions_[size_t(sample)]);
  return known != 0;
}

bool EdgeCollapseDecimator::boundaryMayShrink() const {
  return options_.cost == CollapseCost::ServedSamples && !options_.fixedBoundary;
}

// Served samples: the increase of their total error (the freed vertices
// count from zero, the placement leaves the sum), and the mean error of
// the samples the new triangles serve. Centroid: the mean triangle error,
// both times. Sums run in sample order, so the result does not depend on
// the history that led to this mesh.
std::pair<double, double> EdgeCollapseDecimator::evaluate(const Plan& plan) {
  if (options_.cost == CollapseCost::Centroid) {
    const double mean = meanError(plan.added);
    return {mean, mean};
  }
  const double placementBefore = weightOf(plan.placement) * homeError_[size_t(plan.placement)];
  if (plan.priced.size() == plan.served.size()) {
    double after = 0.0, before = 0.0, weightSum = 0.0;
    for (size_t i = 0; i < plan.served.size(); ++i) {
      const int sample = plan.served[i];
      const double weight = weightOf(sample);
      after += weight * sampleError(servingTriangle(plan, i), sample);
      before += weight * homeError_[size_t(sample)];
      weightSum += weight;
    }
    return {after - before - placementBefore, weightSum > 0.0 ? after / weightSum : 0.0};
  }
  // A subset priced: each priced sample's change of error (paired, since
  // a sample's error before and after are close; a freed vertex's before
  // is 0) stands for the samples it was chosen for.
  double before = 0.0, weightSum = 0.0, change = 0.0;
  for (const int sample : plan.served) {
    const double weight = weightOf(sample);
    before += weight * homeError_[size_t(sample)];
    weightSum += weight;
  }
  for (const PricedSample& priced : plan.priced) {
    const size_t i = size_t(priced.index);
    const int sample = plan.served[i];
    const double after = sampleError(servingTriangle(plan, i), sample);
    change += priced.scale * weightOf(sample) * (after - homeError_[size_t(sample)]);
  }
  return {change - placementBefore, weightSum > 0.0 ? (before + change) / weightSum : 0.0};
}

// Costs a batch of edges: every candidate collapse is simulated first, the
// triangle errors they need are computed together (in parallel), then each
// edge takes its cheapest valid candidate (ties: candidate order).
void EdgeCollapseDecimator::costEdges(const std::vector<Edge>& edges, ProgressReporter* progress) {
  std::vector<EdgeState> states = priceEdges(edges, Resort::None, progress);
  for (size_t i = 0; i < edges.size(); ++i) commit(edges[i], std::move(states[i]));
}

void EdgeCollapseDecimator::commit(const Edge& edge, EdgeState state) {
  state.stamp = nextStamp_++;
  ++statistics_.edgesCosted;
  if (std::isfinite(state.cost)) heap_.push({state.cost, edge.first, edge.second, state.stamp});
  edges_[edge] = std::move(state);
}

std::vector<EdgeCollapseDecimator::EdgeState> EdgeCollapseDecimator::priceEdges(const std::vector<Edge>& edges,
                                                                                Resort resort,
                                                                                ProgressReporter* progress) {
  struct Candidate {
    size_t edge;
    Plan plan;
  };
  std::vector<Candidate> plans;
  std::vector<EdgeState> states(edges.size());
  std::vector<Triangle> needed;
  std::vector<SampleReconstruction> neededSamples;
  const int pieces = resort == Resort::Removals ? piecesWithout({}) : 0;
  for (size_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = edges[i];
    const std::vector<std::pair<int, PlacementKind>> tries =
        resort == Resort::Removals
            ? std::vector<std::pair<int, PlacementKind>>{{b, PlacementKind::Removal}, {a, PlacementKind::Removal}}
            : candidates(a, b, states[i]);
    for (const auto& [placement, kind] : tries) {
      Plan plan;
      const bool valid = kind == PlacementKind::Removal
                             ? simulateRemoval(placement == a ? b : a, placement, pieces, plan)
                             : simulate(a, b, placement, kind, plan, resort == Resort::StraightStretches);
      if (!valid) continue;
      if (options_.cost == CollapseCost::Centroid) {
        needed.insert(needed.end(), plan.added.begin(), plan.added.end());
      } else {
        const std::vector<SampleReconstruction> requests = pricedRequests(plan);
        neededSamples.insert(neededSamples.end(), requests.begin(), requests.end());
      }
      plans.push_back({i, std::move(plan)});
    }
  }
  if (options_.cost == CollapseCost::Centroid) {
    ensureErrors(needed, progress);
  } else {
    ensureSampleErrors(neededSamples, progress);
  }
  for (Candidate& candidate : plans) {
    EdgeState& state = states[candidate.edge];
    const auto [cost, error] = evaluate(candidate.plan);
    if (options_.maxError > 0.0 && error > options_.maxError) {
      state.lowestRefusedError = std::min(state.lowestRefusedError, error);
      continue;
    }
    if (cost < state.cost) {
      state.cost = cost;
      state.error = error;
      state.plan = std::move(candidate.plan);
    }
  }
  return states;
}

// ------------------------------------------------------------ collapse --

// The heap's top after dropping stale entries and re-checking the top's
// cost, or nullptr if no valid collapse is left.
const EdgeCollapseDecimator::HeapEntry* EdgeCollapseDecimator::peekValid() {
  while (!heap_.empty()) {
    const HeapEntry top = heap_.top();
    const auto state = edges_.find({top.first, top.second});
    if (state == edges_.end() || state->second.stamp != top.stamp) {
      heap_.pop();
      ++statistics_.staleEntriesSkipped;
      continue;
    }
    // A sample far away may have been freed or taken since this edge was
    // costed: cost it again; if anything changed, the new entry competes.
    const double oldCost = state->second.cost;
    const int oldPlacement = state->second.plan.placement;
    heap_.pop();
    costEdges({{top.first, top.second}});
    const EdgeState& fresh = edges_.at({top.first, top.second});
    if (fresh.cost == oldCost && fresh.plan.placement == oldPlacement) return &heap_.top();
    ++statistics_.collapseChecksFailed;
  }
  return lastResort();
}

// No collapse is valid, none refused by the threshold either: only now
// may a reference leave a straight stretch of the boundary (staysInside).
// On a lattice of samples every corridor's sides are such stretches, and
// without this a level whose corridors stand two references wide stops
// far above the count asked for (oacmpdm1: 133 of 469 samples for any
// target). Only as a last resort, because taking these whenever they are
// cheapest changed selections that never got stuck, for the worse on the
// built-in scene (docs/history/RESULTS-2026-11.md, "References off straight stretches of
// the boundary"). If none of those is valid (none refused either), a
// boundary reference may leave with all its triangles (simulateRemoval):
// no collapse ever cuts a ring of triangles, so a loop of corridors
// otherwise stops where its ring is as thin as it can be (oacmpdm1 at 66
// samples). The rules depend on the mesh alone: every edge is priced with
// them and only the cheapest keeps that price (the others' refusals would
// count as ordinary ones and stop a later search); if it is asked for
// again, its entry fails the check at the top (an ordinary price) and
// this runs again on the same mesh.
const EdgeCollapseDecimator::HeapEntry* EdgeCollapseDecimator::lastResort() {
  if (!boundaryMayShrink() || std::isfinite(lowestRefusedError())) return nullptr;
  const std::vector<Edge> edges = liveEdges();
  if (const HeapEntry* stretch = commitCheapest(edges, priceEdges(edges, Resort::StraightStretches))) {
    ++statistics_.straightStretchSearches;
    return stretch;
  }
  if (std::isfinite(lowestRefusedError())) return nullptr;  // over the threshold: the stop reports it
  const HeapEntry* removal = commitCheapest(edges, priceEdges(edges, Resort::Removals));
  if (removal) ++statistics_.removals;
  return removal;
}

const EdgeCollapseDecimator::HeapEntry* EdgeCollapseDecimator::commitCheapest(const std::vector<Edge>& edges,
                                                                              std::vector<EdgeState> states) {
  size_t best = edges.size();
  for (size_t i = 0; i < edges.size(); ++i) {
    if (std::isfinite(states[i].cost) && (best == edges.size() || states[i].cost < states[best].cost)) best = i;
  }
  if (best == edges.size()) {
    for (size_t i = 0; i < edges.size(); ++i) commit(edges[i], std::move(states[i]));
    return nullptr;
  }
  commit(edges[best], std::move(states[best]));
  return &heap_.top();
}

std::vector<EdgeCollapseDecimator::Edge> EdgeCollapseDecimator::liveEdges() const {
  std::vector<Edge> edges;
  edges.reserve(edges_.size());
  for (const auto& [edge, state] : edges_) edges.push_back(edge);
  return edges;
}

std::optional<Collapse> EdgeCollapseDecimator::peekNextCollapse() {
  const HeapEntry* top = peekValid();
  if (!top) return std::nullopt;
  return logEntry({top->first, top->second}, edges_.at({top->first, top->second}));
}

Collapse EdgeCollapseDecimator::logEntry(const Edge& edge, const EdgeState& state) const {
  Collapse collapse;
  collapse.first = edge.first;
  collapse.second = edge.second;
  if (state.plan.kind == PlacementKind::Removal) {  // the reference that leaves first
    collapse.first = edge.first == state.plan.placement ? edge.second : edge.first;
    collapse.second = state.plan.placement;
  }
  collapse.placement = state.plan.placement;
  collapse.kind = state.plan.kind;
  collapse.cost = state.cost;
  collapse.error = state.error;
  for (int t : state.plan.removed) collapse.removed.push_back(canonicalTriangle(triangles_[size_t(t)]));
  collapse.added = state.plan.added;
  std::sort(collapse.removed.begin(), collapse.removed.end());
  return collapse;
}

double EdgeCollapseDecimator::nextCost() {
  const HeapEntry* top = peekValid();
  return top ? top->cost : kInfinity;
}

bool EdgeCollapseDecimator::isValidCollapse(int first, int second, int placement) const {
  if (placement != first && placement != second && isVertex_[size_t(placement)]) return false;
  Plan plan;
  return simulate(first, second, placement, PlacementKind::First, plan);
}

bool EdgeCollapseDecimator::isValidRemoval(int leaving, int staying) const {
  if (!isVertex_[size_t(leaving)] || !isVertex_[size_t(staying)]) return false;
  Plan plan;
  return simulateRemoval(leaving, staying, piecesWithout({}), plan);
}

std::optional<Collapse> EdgeCollapseDecimator::evaluateCollapse(int first, int second, int placement) {
  if (placement != first && placement != second && isVertex_[size_t(placement)]) return std::nullopt;
  Plan plan;
  const PlacementKind kind = placement == first ? PlacementKind::First : placement == second ? PlacementKind::Second
                                                                                              : PlacementKind::Midpoint;
  if (!simulate(first, second, placement, kind, plan)) return std::nullopt;
  if (options_.cost == CollapseCost::Centroid) {
    ensureErrors(plan.added);
  } else {
    ensureSampleErrors(pricedRequests(plan));
  }
  const auto [cost, error] = evaluate(plan);
  if (options_.maxError > 0.0 && error > options_.maxError) return std::nullopt;
  Collapse collapse;
  collapse.first = first;
  collapse.second = second;
  collapse.placement = placement;
  collapse.kind = kind;
  collapse.cost = cost;
  collapse.error = error;
  for (int t : plan.removed) collapse.removed.push_back(canonicalTriangle(triangles_[size_t(t)]));
  std::sort(collapse.removed.begin(), collapse.removed.end());
  collapse.added = plan.added;
  return collapse;
}

void EdgeCollapseDecimator::apply(const Edge& edge, const EdgeState& state) {
  const auto [a, b] = edge;
  const Plan& plan = state.plan;
  log_.push_back(logEntry(edge, state));
  for (int t : plan.removed) {
    alive_[size_t(t)] = 0;
    for (int v : triangles_[size_t(t)]) {
      auto& list = incident_[size_t(v)];
      list.erase(std::find(list.begin(), list.end(), t));
    }
  }
  for (const Triangle& t : plan.added) {
    const int id = int(triangles_.size());
    triangles_.push_back(t);
    alive_.push_back(1);
    for (int v : t) incident_[size_t(v)].push_back(id);
  }

  // Served samples move to the new triangles; the placement is a reference
  // now. If it was served by a triangle outside the collapse (on a shared
  // edge), that triangle's edges must be re-costed too.
  int placementHome = -1;
  std::set<int> gainedSamples;  // existing triangles that now serve samples outside the mesh
  if (options_.cost == CollapseCost::ServedSamples) {
    if (plan.priced.size() < plan.served.size()) {  // the samples left out of the price have errors from now on
      ensureSampleErrors(servedRequests(plan));
    }
    const int firstAdded = int(triangles_.size()) - int(plan.added.size());
    served_.resize(triangles_.size());
    for (int t : plan.removed) served_[size_t(t)].clear();
    placementHome = home_[size_t(plan.placement)];
    if (placementHome >= 0) {
      auto& list = served_[size_t(placementHome)];
      list.erase(std::remove(list.begin(), list.end(), plan.placement), list.end());
      if (!alive_[size_t(placementHome)]) placementHome = -1;
    }
    home_[size_t(plan.placement)] = -1;
    homeError_[size_t(plan.placement)] = 0.0;
    for (size_t i = 0; i < plan.served.size(); ++i) {
      const int sample = plan.served[i];
      const int previous = home_[size_t(sample)];
      if (previous >= 0 && alive_[size_t(previous)]) {  // an outside sample a new triangle is nearer to
        auto& list = served_[size_t(previous)];
        list.erase(std::remove(list.begin(), list.end(), sample), list.end());
      }
      const int home = plan.servedBy[i] >= 0 ? firstAdded + plan.servedBy[i] : -1 - plan.servedBy[i];
      home_[size_t(sample)] = home;
      homeError_[size_t(sample)] = sampleError(sortedTriangle(servingTriangle(plan, i)), sample);
      homeRank_[size_t(sample)] = plan.servedRank[i];
      served_[size_t(home)].push_back(sample);
      if (home < firstAdded) gainedSamples.insert(home);
      if (plan.servedRank[i].distance > 0.0) {
        outside_.insert(sample);
      } else {
        outside_.erase(sample);
      }
    }
    outside_.erase(plan.placement);
  }

  isVertex_[size_t(a)] = isVertex_[size_t(b)] = 0;
  isVertex_[size_t(plan.placement)] = 1;
  vertexCount_ -= 1;
  countedCount_ += counts(plan.placement) - counts(a) - counts(b);
  for (auto it = edges_.begin(); it != edges_.end();) {
    it = (it->first.first == a || it->first.second == a || it->first.first == b || it->first.second == b) ? edges_.erase(it)
                                                                                                         : std::next(it);
  }

  // Re-cost the edges whose updated triangles changed (those touching p
  // or a neighbour of p), and those whose midpoint candidate changed: it
  // was p, or a or b is now free and nearer. Re-costing lazily, only the
  // placement's edges are costed now, and those without a finite cost:
  // they have no heap entry that would bring them back when they became
  // valid. The others are costed again when they reach the heap's top.
  const auto costedNow = [&](const Edge& other, const EdgeState* known) {
    if (!options_.lazyRecosting || other.first == plan.placement || other.second == plan.placement) return true;
    return !known || !std::isfinite(known->cost);
  };
  std::set<Edge> affected;
  std::vector<int> around = neighboursOf(plan.placement);
  around.push_back(plan.placement);
  if (plan.kind == PlacementKind::Removal) {  // the fan's outline, not all of it around the placement
    for (const Triangle& t : log_.back().removed) around.insert(around.end(), t.begin(), t.end());
  }
  if (placementHome >= 0) gainedSamples.insert(placementHome);
  for (int t : gainedSamples) around.insert(around.end(), triangles_[size_t(t)].begin(), triangles_[size_t(t)].end());
  for (int w : around) {
    for (int x : neighboursOf(w)) {
      const Edge other{std::min(w, x), std::max(w, x)};
      const auto known = edges_.find(other);
      if (costedNow(other, known == edges_.end() ? nullptr : &known->second)) affected.insert(other);
    }
  }
  for (const auto& [other, otherState] : edges_) {
    if (!costedNow(other, &otherState)) continue;
    const glm::dvec2 midpoint = 0.5 * (positions_[size_t(other.first)] + positions_[size_t(other.second)]);
    bool changed = otherState.midpointSample == plan.placement;
    for (int freed : {a, b}) {
      changed |= freed != plan.placement && glm::length(positions_[size_t(freed)] - midpoint) < otherState.midpointDistance;
    }
    if (changed) affected.insert(other);
  }
  costEdges(std::vector<Edge>(affected.begin(), affected.end()));
}

bool EdgeCollapseDecimator::step() {
  if (options_.targetSamples > 0 && countedCount_ <= options_.targetSamples) {
    stopReason_ = StopReason::TargetReached;
    return false;
  }
  const HeapEntry* top = peekValid();
  if (!top) {
    stopReason_ = std::isfinite(lowestRefusedError()) ? StopReason::MaxError : StopReason::NoValidCollapse;
    return false;
  }
  const Edge edge{top->first, top->second};
  heap_.pop();
  const EdgeState state = edges_.at(edge);
  apply(edge, state);
  stopReason_ = StopReason::None;
  return true;
}

StopReason EdgeCollapseDecimator::run(ProgressReporter* progress) {
  while (true) {
    if (interruptRequested()) {
      stopReason_ = StopReason::Interrupted;
      break;
    }
    if (!step()) break;
    if (progress) {
      char status[96];
      std::snprintf(status, sizeof status, "samples %d  cost %.3f", vertexCount_, log_.back().cost);
      progress->setStatus(status);
      progress->setTotal(log_.size() + expectedRemainingCollapses());
      progress->advance();
    }
  }
  return stopReason_;
}

double EdgeCollapseDecimator::lowestRefusedError() const {
  double lowest = kInfinity;
  for (const auto& [edge, state] : edges_) lowest = std::min(lowest, state.lowestRefusedError);
  return lowest;
}

size_t EdgeCollapseDecimator::expectedRemainingCollapses() const {
  const int floorCount = std::max(3, options_.targetSamples);
  size_t remaining = size_t(std::max(0, countedCount_ - floorCount));
  const size_t window = 32;
  if (options_.maxError > 0.0 && log_.size() > window) {
    const double rise = log_.back().error - log_[log_.size() - 1 - window].error;
    if (rise > 0.0) {
      const double toThreshold = std::max(0.0, options_.maxError - log_.back().error);
      remaining = std::min(remaining, size_t(toThreshold / rise * double(window)) + 1);
    }
  }
  return remaining;
}

// -------------------------------------------------------------- replay --

namespace {

std::vector<Triangle> replace(std::vector<Triangle> triangles, const std::vector<Triangle>& remove,
                              const std::vector<Triangle>& add) {
  for (const Triangle& t : remove) {
    const auto it = std::find(triangles.begin(), triangles.end(), t);
    TRIWALK_CHECK(it != triangles.end(), "collapse log does not match the mesh");
    triangles.erase(it);
  }
  triangles.insert(triangles.end(), add.begin(), add.end());
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

}  // namespace

std::vector<Triangle> replayForward(std::vector<Triangle> initial, std::span<const Collapse> log, size_t steps) {
  for (size_t i = 0; i < std::min(steps, log.size()); ++i) initial = replace(std::move(initial), log[i].removed, log[i].added);
  return initial;
}

std::vector<Triangle> replayBackward(std::vector<Triangle> final, std::span<const Collapse> log, size_t steps) {
  for (size_t i = 0; i < std::min(steps, log.size()); ++i) {
    const Collapse& collapse = log[log.size() - 1 - i];
    final = replace(std::move(final), collapse.added, collapse.removed);
  }
  return final;
}

int samplesAfter(int initialSamples, std::span<const Collapse> log, size_t steps) {
  const auto end = log.begin() + ptrdiff_t(std::min(steps, log.size()));
  return initialSamples - int(std::count_if(log.begin(), end, [](const Collapse& c) { return c.kind != PlacementKind::Relocation; }));
}

std::optional<size_t> lastStepWithSamples(int initialSamples, std::span<const Collapse> log, int samples) {
  std::optional<size_t> last;
  int count = initialSamples;
  for (size_t step = 0; step <= log.size(); ++step) {
    if (step > 0 && log[step - 1].kind != PlacementKind::Relocation) --count;
    if (count == samples) last = step;
  }
  return last;
}

}  // namespace triwalk
