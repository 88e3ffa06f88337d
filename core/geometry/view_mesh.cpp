#include "core/geometry/view_mesh.h"

#include "core/support/errors.h"

#include <algorithm>
#include <limits>
#include <map>
#include <tuple>

namespace triwalk {

ViewMesh::ViewMesh(std::vector<glm::dvec2> positions, std::vector<Triangle> triangles,
                   std::shared_ptr<const WalkableRegion> region)
    : positions_(std::move(positions)), triangles_(std::move(triangles)), region_(std::move(region)) {
  trianglesOfSample_.resize(positions_.size());
  std::map<std::pair<int, int>, std::pair<int, int>> edges;  // directed edge -> (triangle, edge index)
  neighbours_.assign(triangles_.size(), {-1, -1, -1});
  for (size_t t = 0; t < triangles_.size(); ++t) {
    for (int e = 0; e < 3; ++e) {
      const int a = triangles_[t][size_t(e)], b = triangles_[t][size_t((e + 1) % 3)];
      TRIWALK_CHECK(a >= 0 && size_t(a) < positions_.size(), "triangle vertex out of range");
      trianglesOfSample_[size_t(a)].push_back(int(t));
      const auto twin = edges.find({b, a});
      if (twin != edges.end()) {
        neighbours_[t][size_t(e)] = twin->second.first;
        neighbours_[size_t(twin->second.first)][size_t(twin->second.second)] = int(t);
      }
      edges[{a, b}] = {int(t), e};
    }
  }
  for (size_t s = 0; s < trianglesOfSample_.size(); ++s) {
    if (!trianglesOfSample_[s].empty()) vertices_.push_back(int(s));
  }
  bounds_.reserve(triangles_.size());
  for (const Triangle& t : triangles_) {
    const glm::dvec2 a = position(t[0]), b = position(t[1]), c = position(t[2]);
    bounds_.push_back({glm::min(glm::min(a, b), c), glm::max(glm::max(a, b), c)});
  }
}

namespace {

// The Delaunay triangles of the chosen samples (canonical, sorted), empty
// when they are fewer than 3 or collinear.
std::vector<Triangle> delaunayOf(const std::vector<glm::dvec2>& positions, std::span<const int> samples) {
  std::vector<int> chosen(samples.begin(), samples.end());
  if (chosen.empty()) {
    for (size_t i = 0; i < positions.size(); ++i) chosen.push_back(int(i));
  }
  if (chosen.size() < 3) return {};
  std::vector<glm::dvec2> subset;
  for (int sample : chosen) subset.push_back(positions[size_t(sample)]);
  std::vector<Triangle> triangles = delaunayTriangles(subset);
  for (Triangle& triangle : triangles) {
    for (int& vertex : triangle) vertex = chosen[size_t(vertex)];
    triangle = canonicalTriangle(triangle);
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

void keepInside(std::vector<Triangle>& triangles, const std::vector<glm::dvec2>& positions, const WalkableRegion* region) {
  if (!region || region->empty()) return;
  std::erase_if(triangles, [&](const Triangle& t) {
    return !region->containsTriangle(positions[size_t(t[0])], positions[size_t(t[1])], positions[size_t(t[2])]);
  });
}

}  // namespace

ViewMesh ViewMesh::delaunay(std::vector<glm::dvec2> positions, std::span<const int> samples, const std::string& subject,
                            const WalkableRegion* region) {
  const size_t chosen = samples.empty() ? positions.size() : samples.size();
  if (chosen < 3) throw InputError(subject, "at least 3 samples are needed to triangulate, got " + std::to_string(chosen));
  std::vector<Triangle> triangles = delaunayOf(positions, samples);
  if (triangles.empty()) throw InputError(subject, "the sample positions are collinear: they do not span an area to triangulate");
  keepInside(triangles, positions, region);
  if (triangles.empty()) throw InputError(subject, "no triangle of the samples lies inside the walkable region");
  return ViewMesh(std::move(positions), std::move(triangles), sharedRegion(region));
}

std::optional<ViewMesh> ViewMesh::tryDelaunay(std::vector<glm::dvec2> positions, std::span<const int> samples,
                                              const WalkableRegion* region) {
  std::vector<Triangle> triangles = delaunayOf(positions, samples);
  keepInside(triangles, positions, region);
  if (triangles.empty()) return std::nullopt;
  return ViewMesh(std::move(positions), std::move(triangles), sharedRegion(region));
}

glm::dvec2 ViewMesh::centroid(int triangle) const {
  const Triangle& t = triangles_[size_t(triangle)];
  return (position(t[0]) + position(t[1]) + position(t[2])) / 3.0;
}

bool ViewMesh::isBoundaryVertex(int sample) const {
  for (int t : trianglesOfSample_[size_t(sample)]) {
    for (int e = 0; e < 3; ++e) {
      const Triangle& triangle = triangles_[size_t(t)];
      if (neighbours_[size_t(t)][size_t(e)] < 0 && (triangle[size_t(e)] == sample || triangle[size_t((e + 1) % 3)] == sample)) {
        return true;
      }
    }
  }
  return false;
}

std::vector<std::pair<int, int>> ViewMesh::boundaryEdges() const {
  std::vector<std::pair<int, int>> edges;
  for (size_t t = 0; t < triangles_.size(); ++t) {
    for (int e = 0; e < 3; ++e) {
      if (neighbours_[t][size_t(e)] < 0) edges.emplace_back(triangles_[t][size_t(e)], triangles_[t][size_t((e + 1) % 3)]);
    }
  }
  return edges;
}

std::vector<int> ViewMesh::trianglesAround(int sample) const {
  if (sample < 0 || size_t(sample) >= trianglesOfSample_.size()) return {};
  return trianglesOfSample_[size_t(sample)];
}

bool ViewMesh::contains(int triangle, glm::dvec2 point) const {
  const Triangle& t = triangles_[size_t(triangle)];
  for (int e = 0; e < 3; ++e) {
    if (orientation(position(t[size_t(e)]), position(t[size_t((e + 1) % 3)]), point) < 0) return false;
  }
  return true;
}

double ViewMesh::distanceToTriangle(int triangle, glm::dvec2 point) const {
  return triwalk::distanceToTriangle(positions_, triangles_[size_t(triangle)], point);
}

int ViewMesh::locate(glm::dvec2 point, int hint) const {
  return locate(point, hint, [&](int v) { return regionSees(v, point); });
}

int ViewMesh::locate(glm::dvec2 point, int hint, const std::function<bool(int)>& sees) const {
  if (triangles_.empty()) return -1;
  int current = hint >= 0 && hint < triangleCount() ? hint : 0;
  // Visibility walk: step across an edge that separates the triangle from
  // the point. Trying the edges from a rotating start keeps the walk from
  // cycling in meshes that are not Delaunay.
  const int maximumSteps = 4 * triangleCount() + 16;
  for (int step = 0; step < maximumSteps; ++step) {
    const Triangle& t = triangles_[size_t(current)];
    int next = -2;
    for (int k = 0; k < 3; ++k) {
      const int e = (k + step) % 3;
      if (orientation(position(t[size_t(e)]), position(t[size_t((e + 1) % 3)]), point) < 0) {
        next = neighbours_[size_t(current)][size_t(e)];
        break;
      }
    }
    if (next == -2) return current;  // inside or on the boundary of current
    if (next == -1) break;           // the point is outside the covered area
    current = next;
  }
  return locateOutside(point, sees);
}

int ViewMesh::locateOutside(glm::dvec2 point, const std::function<bool(int)>& sees) const {
  // The walk stops at the boundary; the point may still lie in another
  // piece of the mesh, or across a hole: the lowest-numbered triangle
  // that holds it. A triangle whose bounds do not hold the point does not
  // (orientation is exact).
  const auto inBounds = [&](const Bounds& b) {
    return point.x >= b.low.x && point.x <= b.high.x && point.y >= b.low.y && point.y <= b.high.y;
  };
  for (int t = 0; t < triangleCount(); ++t) {
    if (inBounds(bounds_[size_t(t)]) && contains(t, point)) return t;
  }
  // Outside every triangle: in (distance, vertices) order, the first
  // triangle whose references see the point has the best rank (any seeing
  // triangle beats every blind one), and if none sees it, the first. A
  // refinement locates hundreds of such points in each mesh it tries (the
  // rim of the region, rooms a tile's edge cut off), so the triangles are
  // not all measured and sorted: they are taken nearest bounds first, and
  // measured only while their bounds' distance could still put them
  // before the nearest measured one. The distance to the bounds, less a
  // nanometre, never exceeds distanceToTriangle's, so the order, and the
  // triangle found, are those of measuring them all.
  using Bound = std::pair<double, int>;
  using Ranked = std::tuple<double, Triangle, int>;
  const auto later = [](const auto& a, const auto& b) { return a > b; };  // min-heaps
  std::vector<Bound> unmeasured;
  unmeasured.reserve(triangles_.size());
  for (int t = 0; t < triangleCount(); ++t) {
    const Bounds& b = bounds_[size_t(t)];
    const glm::dvec2 gap = glm::max(glm::max(b.low - point, point - b.high), glm::dvec2(0.0));
    unmeasured.emplace_back(glm::length(gap) * (1.0 - 1e-9) - 1e-9, t);
  }
  std::make_heap(unmeasured.begin(), unmeasured.end(), later);
  std::vector<Ranked> measured;
  int nearest = -1;
  for (;;) {
    while (!unmeasured.empty() && (measured.empty() || unmeasured.front().first <= std::get<0>(measured.front()))) {
      std::pop_heap(unmeasured.begin(), unmeasured.end(), later);
      const int t = unmeasured.back().second;
      unmeasured.pop_back();
      measured.emplace_back(distanceToTriangle(t, point), sortedTriangle(triangles_[size_t(t)]), t);
      std::push_heap(measured.begin(), measured.end(), later);
    }
    if (measured.empty()) return nearest;
    std::pop_heap(measured.begin(), measured.end(), later);
    const auto [distance, vertices, t] = measured.back();
    measured.pop_back();
    if (nearest < 0) nearest = t;
    if (!rankTriangle(triangles_[size_t(t)], distance, sees).blind) return t;
  }
}

ServingRank ViewMesh::servingRank(int triangle, glm::dvec2 point) const {
  return rankTriangle(triangles_[size_t(triangle)], distanceToTriangle(triangle, point),
                      [&](int v) { return regionSees(v, point); });
}

bool ViewMesh::regionSees(int reference, glm::dvec2 point) const {
  return !region_ || region_->lineOfSight(position(reference), point);
}

}  // namespace triwalk
