#pragma once
// A triangulation of sample positions in the walkthrough plane (x, y):
// the Delaunay triangulation of the dense capture, a decimated mesh, or a
// baseline's selection. Vertices are sample indices of the data set.
// Holds adjacency and the boundary, and locates the triangle around a
// point by walking from a hint (the viewer's last triangle).

#include "core/geometry/planar_geometry.h"
#include "core/geometry/walkable_region.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <compare>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace triwalk {

// How well a triangle serves a position outside every triangle: first
// whether its three references see the position (line of sight inside the
// walkable region), then how near it is, then (ties, such as a corner two
// triangles share) the lower sorted vertex triple. Inside a triangle the
// distance is 0 and the position is never blind.
struct ServingRank {
  bool blind = false;
  double distance = 0.0;
  Triangle vertices{};  // sorted
  auto operator<=>(const ServingRank&) const = default;
};

// The rank of a triangle at distance from a position (0 inside): blind
// when outside and some reference v does not see the position, sees(v).
// ViewMesh::locate and the decimator rank with this one rule.
template <typename Sees>
ServingRank rankTriangle(const Triangle& triangle, double distance, Sees&& sees) {
  const bool blind = distance > 0.0 && !std::all_of(triangle.begin(), triangle.end(), sees);
  return {blind, distance, sortedTriangle(triangle)};
}

class ViewMesh {
public:
  ViewMesh() = default;
  // positions: (x, y) of every sample of the data set by index;
  // triangles: counter-clockwise sample indices; region: the walkable
  // region, for locating positions outside every triangle (none: nearest).
  ViewMesh(std::vector<glm::dvec2> positions, std::vector<Triangle> triangles,
           std::shared_ptr<const WalkableRegion> region = nullptr);

  // The Delaunay triangulation of the given samples (all when empty).
  // With a region, only its triangles that lie inside the region are
  // kept: no view triangle spans a wall or a pillar, and the references
  // of each see each other's space (a region that is one convex room,
  // such as a rectangle, keeps every triangle). Throws InputError naming
  // subject if the samples are collinear or fewer than 3, or if no
  // triangle lies inside the region.
  static ViewMesh delaunay(std::vector<glm::dvec2> positions, std::span<const int> samples, const std::string& subject,
                           const WalkableRegion* region = nullptr);
  // The same, or nothing when no triangle is left.
  static std::optional<ViewMesh> tryDelaunay(std::vector<glm::dvec2> positions, std::span<const int> samples,
                                             const WalkableRegion* region = nullptr);

  const std::vector<Triangle>& triangles() const { return triangles_; }
  const std::vector<int>& vertices() const { return vertices_; }  // sorted sample indices
  const std::vector<glm::dvec2>& positions() const { return positions_; }
  int triangleCount() const { return int(triangles_.size()); }
  int vertexCount() const { return int(vertices_.size()); }
  glm::dvec2 position(int sample) const { return positions_[size_t(sample)]; }
  glm::dvec2 centroid(int triangle) const;

  // Triangle across edge (t[edge], t[edge + 1 mod 3]), -1 on the boundary.
  int neighbour(int triangle, int edge) const { return neighbours_[size_t(triangle)][size_t(edge)]; }
  bool isBoundaryVertex(int sample) const;
  // Boundary edges, oriented with the mesh on their left.
  std::vector<std::pair<int, int>> boundaryEdges() const;
  // Triangles that use a sample, in index order.
  std::vector<int> trianglesAround(int sample) const;

  const std::shared_ptr<const WalkableRegion>& region() const { return region_; }

  bool contains(int triangle, glm::dvec2 point) const;
  // The triangle containing point, walking from hint (any triangle or -1).
  // Outside the covered area: the best ServingRank (the nearest triangle
  // whose references see the point, else the nearest), ties to the lower
  // sorted vertex triple. -1 only if empty.
  int locate(glm::dvec2 point, int hint = -1) const;
  // The same, where sees(v) says whether reference v sees the point: a
  // caller that locates the same points in many meshes remembers the
  // region's lines of sight instead of tracing them in each.
  int locate(glm::dvec2 point, int hint, const std::function<bool(int)>& sees) const;
  ServingRank servingRank(int triangle, glm::dvec2 point) const;
  // Distance from point to a triangle (0 inside).
  double distanceToTriangle(int triangle, glm::dvec2 point) const;

private:
  // Axis-aligned bounds of a triangle, which a point outside them is
  // outside of, and at least as far from.
  struct Bounds {
    glm::dvec2 low, high;
  };
  int locateOutside(glm::dvec2 point, const std::function<bool(int)>& sees) const;
  // Whether a reference sees point across the region (no region: always).
  bool regionSees(int reference, glm::dvec2 point) const;

  std::vector<glm::dvec2> positions_;
  std::vector<Triangle> triangles_;
  std::vector<std::array<int, 3>> neighbours_;
  std::vector<Bounds> bounds_;  // per triangle
  std::vector<int> vertices_;
  std::vector<std::vector<int>> trianglesOfSample_;
  std::shared_ptr<const WalkableRegion> region_;
};

}  // namespace triwalk
