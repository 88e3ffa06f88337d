#include "core/selection/collapse/collapse_mesh.h"

#include <algorithm>
#include <set>

namespace triwalk {

namespace {

bool hasVertex(const Triangle& t, int v) {
  return t[0] == v || t[1] == v || t[2] == v;
}

}  // namespace

CollapseMesh::CollapseMesh(const ViewMesh& mesh)
    : positions_(mesh.positions()),
      triangles_(mesh.triangles()),
      alive_(mesh.triangles().size(), 1),
      incident_(mesh.positions().size()),
      isVertex_(mesh.positions().size(), 0),
      vertexCount_(mesh.vertexCount()),
      aliveCount_(int(mesh.triangles().size())),
      region_(mesh.region()) {
  for (size_t t = 0; t < triangles_.size(); ++t) {
    for (int v : triangles_[t]) incident_[size_t(v)].push_back(int(t));
  }
  for (int v : mesh.vertices()) isVertex_[size_t(v)] = 1;
}

std::vector<int> CollapseMesh::neighboursOf(int vertex) const {
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

std::vector<int> CollapseMesh::edgeTriangles(int a, int b) const {
  std::vector<int> shared;
  for (int t : incident_[size_t(a)]) {
    if (hasVertex(triangles_[size_t(t)], b)) shared.push_back(t);
  }
  return shared;
}

std::vector<int> CollapseMesh::boundaryNeighbours(int vertex) const {
  std::vector<int> result;
  for (int w : neighboursOf(vertex)) {
    if (edgeTriangles(vertex, w).size() == 1) result.push_back(w);
  }
  return result;
}

bool CollapseMesh::onOpenSegment(int sample, int from, int to) const {
  const glm::dvec2 p = position(sample), a = position(from), b = position(to);
  if (orientation(a, b, p) != 0) return false;
  const double along = glm::dot(p - a, b - a);
  return along > 0.0 && along < glm::dot(b - a, b - a);
}

int CollapseMesh::piecesWithout(const std::vector<int>& removed) const {
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

std::vector<CollapseMesh::Edge> CollapseMesh::edges() const {
  std::set<Edge> edges;
  for (size_t t = 0; t < triangles_.size(); ++t) {
    if (!alive_[t]) continue;
    const Triangle& tri = triangles_[t];
    for (int e = 0; e < 3; ++e) {
      const int a = tri[size_t(e)], b = tri[size_t((e + 1) % 3)];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return {edges.begin(), edges.end()};
}

int CollapseMesh::apply(int a, int b, const CollapsePlan& plan) {
  for (int t : plan.removed) {
    alive_[size_t(t)] = 0;
    for (int v : triangles_[size_t(t)]) {
      auto& list = incident_[size_t(v)];
      list.erase(std::find(list.begin(), list.end(), t));
    }
  }
  const int firstAdded = int(triangles_.size());
  for (const Triangle& t : plan.added) {
    const int id = int(triangles_.size());
    triangles_.push_back(t);
    alive_.push_back(1);
    for (int v : t) incident_[size_t(v)].push_back(id);
  }
  aliveCount_ += int(plan.added.size()) - int(plan.removed.size());
  isVertex_[size_t(a)] = isVertex_[size_t(b)] = 0;
  isVertex_[size_t(plan.placement)] = 1;
  vertexCount_ -= 1;
  return firstAdded;
}

ViewMesh CollapseMesh::viewMesh() const {
  std::vector<Triangle> triangles;
  for (size_t t = 0; t < triangles_.size(); ++t) {
    if (alive_[t]) triangles.push_back(canonicalTriangle(triangles_[t]));
  }
  std::sort(triangles.begin(), triangles.end());
  return ViewMesh(positions_, std::move(triangles), region_);
}

}  // namespace triwalk
