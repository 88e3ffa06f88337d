// Baselines that know the walls (core/selection/walking_distances.h), on
// a hairpin corridor whose answers are known: two straight corridors 1 m
// wide, 10 m long, side by side behind a 0.2 m wall and joined at their
// east end. By straight line the corridors are 1.2 m apart; by walking,
// their west ends are 20 m apart.

#include "core/geometry/view_mesh.h"
#include "core/selection/baselines.h"
#include "core/selection/walking_distances.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

using namespace triwalk;

namespace {

WalkableRegion hairpin() {
  RegionPolygon polygon;
  polygon.outer = {{0, 0}, {10, 0}, {10, 2.2}, {0, 2.2}, {0, 1.2}, {9, 1.2}, {9, 1.0}, {0, 1.0}};
  return WalkableRegion({polygon}, "hairpin");
}

// Samples 0.25 m apart inside the region.
std::vector<glm::dvec2> latticeIn(const WalkableRegion& region) {
  std::vector<glm::dvec2> positions;
  for (double y = 0.125; y < 2.2; y += 0.25) {
    for (double x = 0.125; x < 10.0; x += 0.25) {
      if (region.contains({x, y})) positions.push_back({x, y});
    }
  }
  return positions;
}

bool inSouthCorridor(glm::dvec2 p) { return p.y < 1.0 && p.x < 9.0; }
bool inNorthCorridor(glm::dvec2 p) { return p.y > 1.2 && p.x < 9.0; }

}  // namespace

TEST_CASE("walking distances go round the wall, straight ones go through it") {
  const WalkableRegion region = hairpin();
  const std::vector<glm::dvec2> positions = latticeIn(region);
  const WalkingDistances walking(positions, region);
  // The two west ends, one above the other across the wall.
  int south = -1, north = -1;
  for (int i = 0; i < int(positions.size()); ++i) {
    if (positions[size_t(i)] == glm::dvec2(0.125, 0.625)) south = i;
    if (positions[size_t(i)] == glm::dvec2(0.125, 1.625)) north = i;
  }
  REQUIRE(south >= 0);
  REQUIRE(north >= 0);
  CHECK(glm::length(positions[size_t(south)] - positions[size_t(north)]) == doctest::Approx(1.0));
  // Round the wall's end at x = 9: at least 2 x 8.875 m, and not much more on this lattice.
  CHECK(walking(south, north) > 2.0 * 8.875);
  CHECK(walking(south, north) < 2.0 * 8.875 * 1.08);
  CHECK(walking(south, north) == walking(north, south));
  CHECK(walking(south, south) == 0.0f);
}

TEST_CASE("k-medoids by walking puts one of 2 medoids in each corridor of the hairpin, by straight line it does not") {
  const WalkableRegion region = hairpin();
  const std::vector<glm::dvec2> positions = latticeIn(region);
  const WalkingDistances walking(positions, region);
  const std::vector<int> byWalking = geodesicKMedoidsSelection(walking, 2);
  REQUIRE(byWalking.size() == 2);
  const glm::dvec2 a = positions[size_t(byWalking[0])], b = positions[size_t(byWalking[1])];
  CHECK(((inSouthCorridor(a) && inNorthCorridor(b)) || (inNorthCorridor(a) && inSouthCorridor(b))));
  // By straight line the corridors are one strip: the two medoids split it
  // west and east, each serving both corridors through the wall.
  const std::vector<int> straight = kMedoidsSelection(positions, 2);
  const glm::dvec2 c = positions[size_t(straight[0])], d = positions[size_t(straight[1])];
  CHECK_FALSE(((inSouthCorridor(c) && inNorthCorridor(d)) || (inNorthCorridor(c) && inSouthCorridor(d))));
}

TEST_CASE("farthest-point sampling by walking: each pick is the farthest left, so the distances never grow") {
  const WalkableRegion region = hairpin();
  const std::vector<glm::dvec2> positions = latticeIn(region);
  const WalkingDistances walking(positions, region);
  const auto picks = farthestPointOrder(walking, 12);
  REQUIRE(picks.size() == 12);
  CHECK(picks[0].first == walking.mostCentral());
  // The most central sample of a hairpin is near its turn.
  CHECK(positions[size_t(picks[0].first)].x > 8.0);
  for (size_t k = 1; k < picks.size(); ++k) {
    // Its distance to the nearest earlier pick is the largest any sample had then...
    for (int i = 0; i < walking.count(); ++i) {
      float nearest = std::numeric_limits<float>::infinity();
      for (size_t j = 0; j < k; ++j) nearest = std::min(nearest, walking(picks[j].first, i));
      CHECK(nearest <= picks[k].second);
    }
    // ...and no later pick is farther from the picks before it than this one was.
    CHECK(picks[k].second <= picks[k - 1].second);
  }
  // The second pick is a west end of the hairpin, a corridor's length away by walking.
  CHECK(positions[size_t(picks[1].first)].x < 0.5);
  CHECK(picks[1].second > 8.5f);
}

TEST_CASE("the region-aware uniform baseline keeps the count in views of triangles: a lone node gets the nearest samples, extra ones leave where nodes crowd") {
  const WalkableRegion region = hairpin();
  const std::vector<glm::dvec2> positions = latticeIn(region);
  const WalkingDistances walking(positions, region);
  auto at = [&](glm::dvec2 p) {
    for (int i = 0; i < int(positions.size()); ++i) {
      if (glm::length(positions[size_t(i)] - p) < 1e-9) return i;
    }
    return -1;
  };
  auto sorted = [](std::vector<int> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  // Every chosen sample is a view of a triangle inside the region.
  auto allServe = [&](const std::vector<int>& chosen) {
    const std::optional<ViewMesh> mesh = ViewMesh::tryDelaunay(positions, chosen, &region);
    return mesh && mesh->vertices() == sorted(chosen);
  };
  // Three nodes of a triangle in the south corridor, and b beside a.
  const int a = at({2.125, 0.375}), b = at({2.375, 0.375}), c = at({2.125, 0.875}), d = at({4.125, 0.625});
  REQUIRE((a >= 0 && b >= 0 && c >= 0 && d >= 0));
  // Over the count: the later of the crowded pair leaves.
  CHECK(regionUniformSelection({a, b, c, d}, walking, positions, region, 3) == sorted({a, c, d}));
  // A lone node in the north corridor, among five in the south: a triangle
  // to the south would cross the wall, so the two samples nearest it by
  // walking join (ties: the lower index), the triangle they make with it
  // keeps it, and two crowded southern nodes leave for them (the later of
  // each pair 0.5 m apart).
  const int e = at({6.125, 0.375}), f = at({6.125, 0.875});
  const int lone = at({0.125, 1.625});
  const int below = at({0.125, 1.375}), beside = at({0.375, 1.625});
  REQUIRE((e >= 0 && f >= 0 && lone >= 0 && below >= 0 && beside >= 0));
  CHECK(!allServe({a, c, d, e, f, lone}));
  const std::vector<int> served = regionUniformSelection({a, c, d, e, f, lone}, walking, positions, region, 6);
  CHECK(served == sorted({a, d, e, lone, below, beside}));
  CHECK(allServe(served));
  // Grown from the south triangle to 6: the farthest samples by walking
  // lie in the north corridor, which gets a triangle too.
  const std::vector<int> grown = regionUniformSelection({a, c, d}, walking, positions, region, 6);
  REQUIRE(grown.size() == 6);
  CHECK(allServe(grown));
  CHECK(std::count_if(grown.begin(), grown.end(), [&](int s) { return inNorthCorridor(positions[size_t(s)]); }) >= 3);
  // The count asked for, every one serving, whatever the lattice gives
  // (the straight lattice's nodes on the wall's line serve nothing).
  for (const int count : {3, 5, 8, 12, 20, 40}) {
    const std::vector<int> lattice = latticeSelection(positions, count);
    const std::vector<int> chosen = regionUniformSelection(lattice, walking, positions, region, count);
    CHECK(chosen.size() == size_t(count));
    CHECK(allServe(chosen));
  }
}
