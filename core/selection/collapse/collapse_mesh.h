#pragma once
// The triangulated views as the decimator changes them: flat arrays of
// positions and triangles (a removed triangle stays in place, marked dead,
// so ids never move), the triangles around each sample, and the topology
// questions the collapse rules ask. Nothing here knows about errors.

#include "core/geometry/planar_geometry.h"
#include "core/geometry/view_mesh.h"
#include "core/selection/collapse/collapse_plan.h"

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace triwalk {

// One key per set of three vertices, whatever their order (sample indices
// below 2^21).
inline uint64_t triangleKey(const Triangle& triangle) {
  const Triangle t = sortedTriangle(triangle);
  return (uint64_t(t[0]) << 42) | (uint64_t(t[1]) << 21) | uint64_t(t[2]);
}

class CollapseMesh {
public:
  using Edge = std::pair<int, int>;  // (lower, higher) sample index

  explicit CollapseMesh(const ViewMesh& mesh);

  const std::vector<glm::dvec2>& positions() const { return positions_; }
  const glm::dvec2& position(int sample) const { return positions_[size_t(sample)]; }
  int sampleCount() const { return int(positions_.size()); }
  const std::shared_ptr<const WalkableRegion>& region() const { return region_; }

  // Every triangle ever made, by id; alive(t) for those in the mesh.
  const Triangle& triangle(int t) const { return triangles_[size_t(t)]; }
  int triangleIds() const { return int(triangles_.size()); }
  bool alive(int t) const { return alive_[size_t(t)] != 0; }
  int triangleCount() const { return aliveCount_; }
  // Whether a sample is a reference (a vertex of the mesh).
  bool isVertex(int sample) const { return isVertex_[size_t(sample)] != 0; }
  int vertexCount() const { return vertexCount_; }

  // The alive triangles of a vertex (ids, in the order they were made).
  const std::vector<int>& incident(int vertex) const { return incident_[size_t(vertex)]; }
  std::vector<int> neighboursOf(int vertex) const;  // sorted
  std::vector<int> edgeTriangles(int a, int b) const;
  std::vector<int> boundaryNeighbours(int vertex) const;
  // Whether a sample lies on the open segment between two others (exact).
  bool onOpenSegment(int sample, int from, int to) const;
  // Edge-connected pieces of the mesh without the given triangles (ids, sorted).
  int piecesWithout(const std::vector<int>& removed) const;
  std::vector<Edge> edges() const;  // sorted

  // Makes a planned collapse of edge (a, b): its triangles replaced, a and
  // b no longer references, its placement one. Returns the id of the
  // first added triangle.
  int apply(int a, int b, const CollapsePlan& plan);

  // The mesh as it stands, triangles canonical and sorted.
  ViewMesh viewMesh() const;

private:
  std::vector<glm::dvec2> positions_;
  std::vector<Triangle> triangles_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> incident_;
  std::vector<char> isVertex_;
  int vertexCount_ = 0;
  int aliveCount_ = 0;
  std::shared_ptr<const WalkableRegion> region_;
};

}  // namespace triwalk
