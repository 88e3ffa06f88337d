// The automatic walkable region on analytic scenes whose answer is known:
// two rooms joined by a doorway, and a scene where nobody can stand.

#include "core/geometry/view_mesh.h"
#include "core/support/errors.h"
#include "render/capture/dataset_capture.h"
#include "render/capture/walkable_area.h"
#include "render/gl/gl_context.h"
#include "scene/scene_description.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <fstream>

namespace triwalk {

namespace {

// Two 4 x 3 m rooms, x in [0, 4] and [4.25, 8.25], y in [0, 3], 2.6 m
// high, split by a 0.25 m wall with a 1 m doorway at y in [1, 2] (2.2 m
// high). The outer walls are 0.25 m thick, so the probe grid (0.25 m
// cells from the scene's lower corner, -0.25) has cell edges on every
// wall face.
constexpr const char* kTwoRooms = R"({
  "name": "two-rooms",
  "walkable_area": {"min": [0.5, 0.5], "max": [3.5, 2.5], "eye_height": 1.6, "floor_height": 0.0},
  "materials": {"plain": {"color": [0.6, 0.6, 0.6]}},
  "objects": [
    {"type": "box", "material": "plain", "min": [-0.75, -0.75, -0.2], "max": [9.0, 3.75, 0.0]},
    {"type": "box", "material": "plain", "min": [-0.25, -0.25, 2.6], "max": [8.5, 3.25, 2.8]},
    {"type": "box", "material": "plain", "min": [-0.25, -0.25, 0.0], "max": [8.5, 0.0, 2.6]},
    {"type": "box", "material": "plain", "min": [-0.25, 3.0, 0.0], "max": [8.5, 3.25, 2.6]},
    {"type": "box", "material": "plain", "min": [-0.25, 0.0, 0.0], "max": [0.0, 3.0, 2.6]},
    {"type": "box", "material": "plain", "min": [8.25, 0.0, 0.0], "max": [8.5, 3.0, 2.6]},
    {"type": "box", "material": "plain", "min": [4.0, 0.0, 0.0], "max": [4.25, 1.0, 2.6]},
    {"type": "box", "material": "plain", "min": [4.0, 2.0, 0.0], "max": [4.25, 3.0, 2.6]},
    {"type": "box", "material": "plain", "min": [4.0, 1.0, 2.2], "max": [4.25, 2.0, 2.6]}
  ]
})";

Scene sceneFrom(const testing::TemporaryDirectory& directory, const std::string& name, const std::string& json) {
  const std::filesystem::path path = directory / name;
  std::ofstream(path) << json;
  return loadSceneDescription(path);
}

}  // namespace

TEST_CASE("two rooms and a doorway: one region of the right area, and no view triangle crosses the wall") {
  testing::TemporaryDirectory directory;
  const Scene scene = sceneFrom(directory, "two_rooms.json", kTwoRooms);
  auto context = createHeadlessContext();
  RegionSearchOptions search;
  search.quiet = true;
  const WalkableRegionProposal proposal = proposeWalkableRegion(scene, search, "two_rooms.json");
  INFO(proposal.reason);
  CHECK(proposal.parts == 1);
  CHECK(proposal.region.polygons().size() == 1);
  CHECK(proposal.floorZ == doctest::Approx(0.0));
  // Positions at least 0.25 m (the head clearance) from every wall: a
  // 3.5 x 2.5 m core in each room, joined through the doorway by 3 x 2
  // cells (0.375 m2).
  const double expected = 2.0 * 3.5 * 2.5 + 0.375;
  CHECK(proposal.region.area() == doctest::Approx(expected).epsilon(0.05));
  CHECK(proposal.region.contains({2.0, 1.5}));
  CHECK(proposal.region.contains({6.0, 1.5}));
  CHECK(proposal.region.contains({4.125, 1.5}));     // in the doorway
  CHECK_FALSE(proposal.region.contains({4.125, 0.5}));  // in the wall

  // Capture over it, and triangulate: every edge that passes from one room
  // to the other goes through the doorway.
  CaptureOptions options;
  options.region = proposal.region;
  options.spacing = 0.25f;
  options.probes = 20;
  const CapturePlan plan = planCapture(scene, options);
  std::vector<glm::dvec2> positions;
  for (const ViewRecord& sample : plan.samples) positions.emplace_back(sample.position);
  for (const ViewRecord& probe : plan.probes) CHECK(proposal.region.contains(glm::dvec2(probe.position)));
  const ViewMesh mesh = ViewMesh::delaunay(positions, {}, "test", &proposal.region);
  int throughDoorway = 0;
  for (const Triangle& t : mesh.triangles()) {
    for (int e = 0; e < 3; ++e) {
      const glm::dvec2 a = mesh.position(t[size_t(e)]), b = mesh.position(t[size_t((e + 1) % 3)]);
      if ((a.x < 4.125) == (b.x < 4.125)) continue;
      const double y = a.y + (4.125 - a.x) * (b.y - a.y) / (b.x - a.x);
      CHECK(y > 1.0);
      CHECK(y < 2.0);
      ++throughDoorway;
    }
  }
  CHECK(throughDoorway > 0);
  // Without the region, Delaunay spans the wall: the check above has teeth.
  const ViewMesh unconstrained = ViewMesh::delaunay(positions, {}, "test");
  int acrossWall = 0;
  for (const Triangle& t : unconstrained.triangles()) {
    for (int e = 0; e < 3; ++e) {
      const glm::dvec2 a = unconstrained.position(t[size_t(e)]), b = unconstrained.position(t[size_t((e + 1) % 3)]);
      if ((a.x < 4.125) == (b.x < 4.125)) continue;
      const double y = a.y + (4.125 - a.x) * (b.y - a.y) / (b.x - a.x);
      acrossWall += y < 1.0 || y > 2.0;
    }
  }
  CHECK(acrossWall > 0);
}

TEST_CASE("a scene where nobody can stand gives a one-line error") {
  testing::TemporaryDirectory directory;
  // A floor under the open sky: never enclosed.
  const Scene scene = sceneFrom(directory, "open.json", R"({
    "name": "open",
    "walkable_area": {"min": [0, 0], "max": [1, 1], "eye_height": 1.6, "floor_height": 0.0},
    "materials": {"plain": {"color": [0.6, 0.6, 0.6]}},
    "objects": [{"type": "box", "material": "plain", "min": [-5, -5, -0.2], "max": [5, 5, 0.0]}]
  })");
  auto context = createHeadlessContext();
  RegionSearchOptions search;
  search.quiet = true;
  testing::requireInputError([&] { proposeWalkableRegion(scene, search, "open.json"); }, "open.json",
                             "no walkable region found");
}

TEST_CASE("a given region stands on the floor under it, not on the level's largest floor elsewhere") {
  testing::TemporaryDirectory directory;
  // The two rooms, plus a 20 x 20 m platform away from them at z = 5: the
  // largest horizontal surface of the scene, but under no part of the region.
  std::string json = kTwoRooms;
  json.insert(json.rfind(']'), R"(, {"type": "box", "material": "plain", "min": [20, 0, 4.8], "max": [40, 20, 5.0]})");
  const Scene scene = sceneFrom(directory, "rooms_and_platform.json", json);
  REQUIRE(dominantFloorHeight(scene) > 4.0f);
  const WalkableRegion region = WalkableRegion::rectangle({0.5, 0.5}, {7.5, 2.5});
  CHECK(floorHeightUnder(scene, region) == doctest::Approx(0.0));
  // Over the platform, the platform: the choice follows the region.
  CHECK(floorHeightUnder(scene, WalkableRegion::rectangle({21, 1}, {39, 19})) == doctest::Approx(5.0));
}

}  // namespace triwalk
