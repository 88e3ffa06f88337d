#pragma once
// Exact planar geometry from CGAL (kept to one translation unit,
// core/geometry/cgal_geometry.cpp, because CGAL is slow to compile): the Delaunay
// triangulation of the sample positions and the orientation predicate
// every validity test of the decimator rests on.

#include <glm/glm.hpp>

#include <array>
#include <span>
#include <vector>

namespace triwalk {

using Triangle = std::array<int, 3>;  // indices, counter-clockwise

// Delaunay triangulation (exact predicates) of distinct points. Triangles
// are counter-clockwise, each rotated to start at its smallest index, and
// sorted, so the result does not depend on CGAL's internal order. Empty
// if all points are collinear or fewer than 3.
std::vector<Triangle> delaunayTriangles(std::span<const glm::dvec2> points);

// Exact sign of the orientation of (a, b, c): +1 counter-clockwise,
// -1 clockwise, 0 collinear.
int orientation(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);

// Distance from point to the closed counter-clockwise triangle (a, b, c):
// exactly 0 inside or on its edges (exact predicate), else to the nearest edge.
double distanceToTriangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 point);
// The same for a triangle of indices into positions.
inline double distanceToTriangle(std::span<const glm::dvec2> positions, const Triangle& t, glm::dvec2 point) {
  return distanceToTriangle(positions[size_t(t[0])], positions[size_t(t[1])], positions[size_t(t[2])], point);
}

// Rotates a triangle to start at its smallest index (same orientation).
Triangle canonicalTriangle(Triangle triangle);

// The vertices in ascending order (orientation lost): the key of a
// triangle whatever its rotation or winding, for caches.
Triangle sortedTriangle(Triangle triangle);

}  // namespace triwalk
