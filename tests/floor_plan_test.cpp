// The generated floor (scene/floor_plan.h): the spec it is asked
// by, the same floor from the same seed, one walkable region that reaches
// every room through its doors and keeps clear of every wall and cabinet,
// and a sample count that grows with the rooms.

#include "core/io/json_fields.h"
#include "scene/floor_plan.h"
#include "scene/scene_description.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <cmath>

namespace triwalk {

namespace {

const nlohmann::json& builtin() {
  static const nlohmann::json description = readJsonFile(builtinScenePath());
  return description;
}

glm::dvec2 point(const nlohmann::json& value) { return {value[0].get<double>(), value[1].get<double>()}; }

}  // namespace

TEST_CASE("builtin-floor specs: columns x rows, an optional seed, and one line for a malformed one") {
  CHECK_FALSE(parseFloorPlanSpec("builtin").has_value());
  CHECK_FALSE(parseFloorPlanSpec("house.ifc").has_value());
  const FloorPlanSize plain = *parseFloorPlanSpec("builtin-floor:8x5");
  CHECK(plain.columns == 8);
  CHECK(plain.rows == 5);
  CHECK(plain.seed == 1);
  CHECK(parseFloorPlanSpec("builtin-floor:3x2:77")->seed == 77);
  for (const char* bad : {"builtin-floor", "builtin-floor:", "builtin-floor:8", "builtin-floor:8x", "builtin-floor:0x3",
                          "builtin-floor:65x1", "builtin-floor:2x2:", "builtin-floor:2x2:x", "builtin-floor:2x2x2",
                          "builtin-floor:-1x2"}) {
    CAPTURE(bad);
    testing::requireInputError([&] { parseFloorPlanSpec(bad); }, "--scene", "a floor is builtin-floor:CxR[:SEED]");
  }
}

TEST_CASE("a floor is the same from the same seed, and another from another") {
  const FloorPlan first = makeFloorPlan({3, 2, 5}, builtin());
  const FloorPlan again = makeFloorPlan({3, 2, 5}, builtin());
  const FloorPlan other = makeFloorPlan({3, 2, 6}, builtin());
  CHECK(first.description.dump() == again.description.dump());
  CHECK(first.region.toJson().dump() == again.region.toJson().dump());
  CHECK(first.description.dump() != other.description.dump());
}

TEST_CASE("a floor's region reaches every room in one piece and keeps clear of its walls and cabinets") {
  const FloorPlan plan = makeFloorPlan({4, 3, 1}, builtin());
  REQUIRE(plan.region.polygons().size() == 1);  // one piece: every room through a door
  const Scene scene = sceneFromDescription(plan.description, "builtin-floor:4x3");
  CHECK(scene.triangleCount() > 1000);
  CHECK(scene.lights.size() == 12 + 2 * 4 + 4);  // a light a room, every 5 m along the two corridors and the spine

  size_t wallPoints = 0, doorPoints = 0;
  for (const nlohmann::json& object : plan.description["objects"]) {
    const std::string type = object["type"];
    if (type == "wall") {
      const glm::dvec2 from = point(object["from"]), to = point(object["to"]);
      const double length = glm::length(to - from);
      for (double along = 0.05; along < length; along += 0.1) {
        bool inOpening = false;
        if (object.contains("openings")) {
          for (const nlohmann::json& opening : object["openings"]) {
            inOpening |= along > opening["start"].get<double>() && along < opening["end"].get<double>();
          }
        }
        const glm::dvec2 p = from + (to - from) * (along / length);
        if (inOpening) {
          doorPoints += plan.region.contains(p);
        } else {
          ++wallPoints;
          CHECK_MESSAGE(!plan.region.contains(p), "a wall at (" << p.x << ", " << p.y << ") is walkable");
        }
      }
    } else if (type == "box" && object["material"] == "bookshelf") {
      const glm::dvec2 lower = point(object["min"]), upper = point(object["max"]);
      for (double x = lower.x; x <= upper.x; x += 0.1) {
        for (double y = lower.y; y <= upper.y; y += 0.1) CHECK_FALSE(plan.region.contains({x, y}));
      }
    }
  }
  CHECK(wallPoints > 1000);
  CHECK(doorPoints > 12);  // the walker passes through the doorways
}

TEST_CASE("a floor's samples grow with its rooms: about 480 for 2 x 1, about 28,800 for 16 x 10") {
  // Samples at the plan's spacing: the region's area times (1 / spacing)^2.
  auto samples = [](int columns, int rows) {
    const FloorPlan plan = makeFloorPlan({columns, rows, 1}, builtin());
    return plan.region.area() / double(plan.sampleSpacing * plan.sampleSpacing);
  };
  CHECK(samples(2, 1) == doctest::Approx(470).epsilon(0.1));
  CHECK(samples(5, 2) == doctest::Approx(1810).epsilon(0.1));
  CHECK(samples(8, 5) == doctest::Approx(7310).epsilon(0.1));
  CHECK(samples(16, 10) == doctest::Approx(27500).epsilon(0.1));
}

}  // namespace triwalk
