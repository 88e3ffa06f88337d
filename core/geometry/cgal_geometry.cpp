// The only translation unit that includes CGAL.

#include "core/geometry/planar_geometry.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <limits>
#include <utility>

namespace triwalk {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;
using Point = Kernel::Point_2;

}  // namespace

Triangle canonicalTriangle(Triangle t) {
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

Triangle sortedTriangle(Triangle t) {
  std::sort(t.begin(), t.end());
  return t;
}

std::vector<Triangle> delaunayTriangles(std::span<const glm::dvec2> points) {
  std::vector<std::pair<Point, int>> input;
  input.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) input.emplace_back(Point(points[i].x, points[i].y), int(i));
  Delaunay triangulation;
  triangulation.insert(input.begin(), input.end());
  std::vector<Triangle> triangles;
  if (triangulation.dimension() < 2) return triangles;
  for (auto face = triangulation.finite_faces_begin(); face != triangulation.finite_faces_end(); ++face) {
    // CGAL faces are counter-clockwise.
    triangles.push_back(canonicalTriangle({face->vertex(0)->info(), face->vertex(1)->info(), face->vertex(2)->info()}));
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

int orientation(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  switch (CGAL::orientation(Point(a.x, a.y), Point(b.x, b.y), Point(c.x, c.y))) {
    case CGAL::LEFT_TURN: return 1;
    case CGAL::RIGHT_TURN: return -1;
    default: return 0;
  }
}

double distanceToTriangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 point) {
  const glm::dvec2 corners[3] = {a, b, c};
  bool inside = true;
  for (int e = 0; e < 3 && inside; ++e) inside = orientation(corners[e], corners[(e + 1) % 3], point) >= 0;
  if (inside) return 0.0;
  double best = std::numeric_limits<double>::max();
  for (int e = 0; e < 3; ++e) {
    // Past either end the distance is to the corner itself, computed the
    // same way from every triangle that shares it (so ties stay exact).
    const glm::dvec2 from = corners[e], to = corners[(e + 1) % 3], edge = to - from;
    const double along = glm::dot(point - from, edge) / glm::dot(edge, edge);
    const glm::dvec2 nearest = along <= 0.0 ? from : along >= 1.0 ? to : from + along * edge;
    best = std::min(best, glm::length(point - nearest));
  }
  return best;
}

}  // namespace triwalk
