// The walkable region: polygons with holes, their validation, and each
// sample's share of the area.

#include "core/geometry/walkable_region.h"
#include "core/support/errors.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

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
