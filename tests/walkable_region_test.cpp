// The walkable region: polygons with holes, their validation, what lies
// in it (points, segments, triangles), and each sample's share of the
// area.

#include "core/geometry/walkable_region.h"
#include "core/support/errors.h"
#include "tests/test_support.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <doctest/doctest.h>

#include <cmath>
#include <random>

namespace triwalk {

TEST_CASE("a region's area, containment and ring orientation") {
  // A 4 x 3 m room with a 1 x 1 m pillar hole, given clockwise (reversed on reading).
  RegionPolygon room;
  room.outer = {{0, 0}, {0, 3}, {4, 3}, {4, 0}};
  room.holes = {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}};
  const WalkableRegion region({room}, "region.json");
  CHECK(region.area() == doctest::Approx(11.0));
  CHECK(region.contains({0.5, 0.5}));
  CHECK(region.contains({4.0, 1.5}));  // on the outer boundary
  CHECK_FALSE(region.contains({1.5, 1.5}));  // in the hole
  CHECK(region.contains({1.0, 1.5}));  // on the hole's boundary: still walkable
  CHECK_FALSE(region.contains({5.0, 1.0}));
  const WalkableRegion reread = WalkableRegion::fromJson(region.toJson(), "again.json");
  CHECK(reread.area() == doctest::Approx(11.0));
}

TEST_CASE("bad regions are refused with a one-line error naming the file and the ring") {
  testing::requireInputError([] { WalkableRegion({}, "r.json"); }, "r.json", "has no polygons");
  testing::requireInputError([] { WalkableRegion({RegionPolygon{{{0, 0}, {1, 0}}, {}}}, "r.json"); }, "r.json",
                             "polygons[0].outer: a ring needs at least 3 points");
  // A bow tie: edges 0 and 2 cross.
  testing::requireInputError([] { WalkableRegion({RegionPolygon{{{0, 0}, {3, 2}, {3, 0}, {0, 1}}, {}}}, "r.json"); },
                             "r.json", "intersects itself");
  testing::requireInputError([] { WalkableRegion({RegionPolygon{{{0, 0}, {1, 1}, {2, 2}}, {}}}, "r.json"); }, "r.json",
                             "encloses no area");
  testing::requireInputError(
      [] { WalkableRegion::fromJson(nlohmann::json::parse(R"({"polygons": [{"outer": [[0, 0], [1, "x"], [0, 1]]}]})"), "r.json"); },
      "r.json", "polygons[0].outer[1]: a point is [x, y]");
  testing::requireInputError([] { WalkableRegion::fromJson(nlohmann::json::parse(R"({"rooms": []})"), "r.json"); },
                             "r.json", "walkable: expected");
  // A hole poking out of its room.
  RegionPolygon leaky{{{0, 0}, {4, 0}, {4, 3}, {0, 3}}, {{{3, 1}, {5, 1}, {5, 2}, {3, 2}}}};
  testing::requireInputError([&] { WalkableRegion({leaky}, "r.json"); }, "r.json", "cross or touch");
}

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// A level's outline in miniature, every edge on the integer grid: a room
// whose ceiling is a skyline of 60 columns 3 to 20 m high, with 1 m
// pillars along its floor, and a second room beside it (200 edges).
std::vector<RegionPolygon> gridLevel() {
  std::mt19937 random(7);
  const int columns = 60;
  std::vector<int> heights;
  for (int x = 0; x < columns; ++x) heights.push_back(3 + int(random() % 18));
  RegionPolygon room;
  room.outer = {{0, 0}, {columns, 0}};
  for (int x = columns - 1; x >= 0; --x) {
    if (room.outer.back().y != heights[size_t(x)]) room.outer.emplace_back(x + 1, heights[size_t(x)]);
    if (x == 0 || heights[size_t(x - 1)] != heights[size_t(x)]) room.outer.emplace_back(x, heights[size_t(x)]);
  }
  for (int x = 2; x + 1 < columns; x += 3) room.holes.push_back({{x, 1}, {x, 2}, {x + 1, 2}, {x + 1, 1}});
  RegionPolygon side{{{columns + 2, 0}, {columns + 6, 0}, {columns + 6, 5}, {columns + 2, 5}}, {}};
  return {room, side};
}

// The same region judged by CGAL: a point is in it when it is in or on an
// outer ring and not strictly inside any of that polygon's holes.
bool oracleContains(const std::vector<RegionPolygon>& polygons, glm::dvec2 p) {
  const Kernel::Point_2 point(p.x, p.y);
  auto side = [&](const Ring& ring) {
    CGAL::Polygon_2<Kernel> polygon;
    for (glm::dvec2 v : ring) polygon.push_back(Kernel::Point_2(v.x, v.y));
    return polygon.bounded_side(point);
  };
  for (const RegionPolygon& polygon : polygons) {
    if (side(polygon.outer) == CGAL::ON_UNBOUNDED_SIDE) continue;
    if (std::none_of(polygon.holes.begin(), polygon.holes.end(),
                     [&](const Ring& hole) { return side(hole) == CGAL::ON_BOUNDED_SIDE; })) {
      return true;
    }
  }
  return false;
}

// Whether a segment lies in a region made of whole grid cells: cut at
// every grid line it crosses, each piece lies in one cell or along one
// cell side, all in or all out, so its middle decides (the region is
// closed, so the cuts themselves follow from the pieces beside them).
bool oracleContainsSegment(const std::vector<RegionPolygon>& polygons, glm::dvec2 a, glm::dvec2 b) {
  std::vector<double> cuts{0.0, 1.0};
  for (int axis = 0; axis < 2; ++axis) {
    if (a[axis] == b[axis]) continue;
    for (double line = std::ceil(std::min(a[axis], b[axis])); line <= std::max(a[axis], b[axis]); line += 1.0) {
      cuts.push_back((line - a[axis]) / (b[axis] - a[axis]));
    }
  }
  std::sort(cuts.begin(), cuts.end());
  if (!oracleContains(polygons, a) || !oracleContains(polygons, b)) return false;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (cuts[k + 1] > cuts[k] && !oracleContains(polygons, a + 0.5 * (cuts[k] + cuts[k + 1]) * (b - a))) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("what lies in a level-like region: points, segments and triangles, against CGAL") {
  const std::vector<RegionPolygon> polygons = gridLevel();
  const WalkableRegion region(polygons, "level.json");
  REQUIRE_FALSE(region.convex());
  size_t edges = 0;
  for (const RegionPolygon& polygon : polygons) {
    edges += polygon.outer.size();
    for (const Ring& hole : polygon.holes) edges += hole.size();
  }
  REQUIRE(edges > 150);

  // Points on a quarter-metre lattice: a quarter of each coordinate on a
  // grid line, so many on walls, corners and pillars' sides.
  std::mt19937 random(11);
  auto point = [&] {
    const double x = -1.0 + 0.25 * double(random() % 285);
    return glm::dvec2(x, -1.0 + 0.25 * double(random() % 93));
  };
  // A lattice point up to reach away from another along each axis.
  auto near = [&](glm::dvec2 from, double reach) {
    const double x = double(random() % 2001) / 1000.0 - 1.0;
    const glm::dvec2 offset = reach * glm::dvec2(x, double(random() % 2001) / 1000.0 - 1.0);
    return glm::round((from + offset) * 4.0) / 4.0;
  };
  auto kernelPoint = [](glm::dvec2 p) { return Kernel::Point_2(p.x, p.y); };
  int inside = 0, onBoundary = 0;
  for (int i = 0; i < 4000; ++i) {
    const glm::dvec2 p = point();
    const bool expected = oracleContains(polygons, p);
    CHECK_MESSAGE(region.contains(p) == expected, "(", p.x, ", ", p.y, ")");
    inside += expected;
    onBoundary += expected && !oracleContains(polygons, p + glm::dvec2(0.125, 0.125));
  }
  CHECK(inside > 1000);
  CHECK(onBoundary > 50);

  // Segments from a few centimetres to the whole level, some along grid
  // lines; triangles of three such points.
  int segmentsInside = 0, trianglesInside = 0;
  for (int i = 0; i < 3000; ++i) {
    const glm::dvec2 a = point();
    const double reach = i % 3 == 0 ? 80.0 : i % 3 == 1 ? 6.0 : 1.5;
    glm::dvec2 b = near(a, reach);
    if (i % 5 == 0) b.y = a.y;
    if (i % 5 == 1) b.x = a.x;
    if (a == b) continue;
    const bool expected = oracleContainsSegment(polygons, a, b);
    CHECK_MESSAGE(region.containsSegment(a, b) == expected, "(", a.x, ", ", a.y, ") to (", b.x, ", ", b.y, ")");
    CHECK(region.lineOfSight(a, b) == expected);
    segmentsInside += expected;

    const glm::dvec2 c = near(a, 4.0);
    if (CGAL::collinear(kernelPoint(a), kernelPoint(b), kernelPoint(c))) continue;
    const bool edgesInside = oracleContainsSegment(polygons, a, b) && oracleContainsSegment(polygons, b, c) &&
                             oracleContainsSegment(polygons, c, a);
    bool aroundPillar = false;
    const CGAL::Triangle_2<Kernel> triangle(kernelPoint(a), kernelPoint(b), kernelPoint(c));
    for (const RegionPolygon& polygon : polygons) {
      for (const Ring& hole : polygon.holes) {
        for (glm::dvec2 v : hole) aroundPillar |= triangle.bounded_side(kernelPoint(v)) == CGAL::ON_BOUNDED_SIDE;
      }
    }
    const bool triangleExpected = edgesInside && !aroundPillar;
    CHECK_MESSAGE(region.containsTriangle(a, b, c) == triangleExpected, "(", a.x, ", ", a.y, "), (", b.x, ", ", b.y,
                  "), (", c.x, ", ", c.y, ")");
    trianglesInside += triangleExpected;
  }
  CHECK(segmentsInside > 300);
  CHECK(trianglesInside > 100);

  // Around each pillar a triangle whose edges pass beside it, refused;
  // beside it one that stops short of it, kept.
  for (const Ring& pillar : polygons[0].holes) {
    const double x = pillar[0].x;
    CHECK(region.containsSegment({x - 1.0, 0.5}, {x + 2.5, 0.5}));
    CHECK(region.containsSegment({x + 2.5, 0.5}, {x + 0.5, 3.0}));
    CHECK(region.containsSegment({x + 0.5, 3.0}, {x - 1.0, 0.5}));
    CHECK_FALSE(region.containsTriangle({x - 1.0, 0.5}, {x + 2.5, 0.5}, {x + 0.5, 3.0}));
    CHECK(region.containsTriangle({x - 1.0, 0.5}, {x - 0.25, 0.5}, {x - 0.25, 2.5}));
  }
}

TEST_CASE("each sample's share of the area: a half on the region's edge, a quarter in its corners") {
  // 5 x 3 samples 1 m apart filling the region [0, 4] x [0, 2] exactly.
  std::vector<glm::dvec2> positions;
  for (int x = 0; x < 5; ++x) {
    for (int y = 0; y < 3; ++y) positions.emplace_back(x, y);
  }
  const std::vector<double> weights = sampleAreaWeights(positions, WalkableRegion::rectangle({0, 0}, {4, 2}));
  // Interior 1 m^2, edge 1/2, corner 1/4; the 8 m^2 over 15 samples average 1.
  const double scale = 15.0 / 8.0;
  CHECK(weights[0] == doctest::Approx(0.25 * scale).epsilon(0.02));   // (0, 0)
  CHECK(weights[1] == doctest::Approx(0.5 * scale).epsilon(0.02));    // (0, 1)
  CHECK(weights[4] == doctest::Approx(1.0 * scale).epsilon(0.02));    // (1, 1)
  CHECK(weights[3] == doctest::Approx(0.5 * scale).epsilon(0.02));    // (1, 0)
  // A hole around (2, 1): that sample's own cell is gone.
  RegionPolygon room{{{0, 0}, {4, 0}, {4, 2}, {0, 2}}, {{{1.5, 0.5}, {2.5, 0.5}, {2.5, 1.5}, {1.5, 1.5}}}};
  const std::vector<double> holed = sampleAreaWeights(positions, WalkableRegion({room}, "test"));
  CHECK(holed[7] < 0.01);  // (2, 1)
  CHECK(holed[4] == doctest::Approx(1.0 * 15.0 / 7.0).epsilon(0.02));
}

}  // namespace triwalk
