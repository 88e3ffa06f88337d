// Where a walker may go once a selection leaves part of a level outside
// its triangles, and how much of it a selection leaves there.

#include "core/geometry/walk_constraint.h"
#include "core/geometry/walkable_region.h"
#include "core/selection/evaluation.h"

#include <doctest/doctest.h>

#include <memory>

namespace triwalk {

namespace {

// An L of corridors one metre wide: the arm along x from 0 to 6, the arm
// along y from 0 to 4. The view triangles cover the x arm only, as a
// selection whose boundary shrank off the y arm leaves it.
const std::vector<glm::dvec2> kCorners = {{0, 0}, {6, 0}, {6, 1}, {0, 1}};
const std::vector<Triangle> kXArm = {{0, 1, 2}, {0, 2, 3}};

std::shared_ptr<const WalkableRegion> lCorridors() {
  RegionPolygon l;
  l.outer = {{0, 0}, {6, 0}, {6, 1}, {1, 1}, {1, 4}, {0, 4}};
  return std::make_shared<const WalkableRegion>(std::vector<RegionPolygon>{l}, "l.json");
}

}  // namespace

TEST_CASE("a walker reaches the corridor a selection left without triangles, and no wall lets it through") {
  const ViewMesh mesh(kCorners, kXArm, lCorridors());
  CHECK(isWalkable(mesh, {3.0, 0.5}));        // on a triangle
  CHECK(isWalkable(mesh, {0.5, 3.5}));        // in the y arm: no triangle, still the level's floor
  CHECK_FALSE(isWalkable(mesh, {3.0, 2.0}));  // inside the L's corner: a wall

  // Up the y arm, off the triangles.
  const glm::vec3 up = constrainedStep(mesh, {0.5f, 0.5f, 1.6f}, {0.0f, 2.0f});
  CHECK(up.x == doctest::Approx(0.5f));
  CHECK(up.y == doctest::Approx(2.5f));
  CHECK(up.z == doctest::Approx(1.6f));
  // Diagonally into the wall: slides along it (the x component).
  const glm::vec3 slide = constrainedStep(mesh, {3.0f, 0.5f, 1.6f}, {0.5f, 1.0f});
  CHECK(slide.x == doctest::Approx(3.5f));
  CHECK(slide.y == doctest::Approx(0.5f));
  // Straight into the y arm's side wall: stays.
  const glm::vec3 stopped = constrainedStep(mesh, {0.5f, 3.5f, 1.6f}, {1.0f, 0.0f});
  CHECK(stopped.x == doctest::Approx(0.5f));
  CHECK(stopped.y == doctest::Approx(3.5f));

  // Without a region the triangles are all a walker knows.
  const ViewMesh trianglesOnly(kCorners, kXArm);
  CHECK_FALSE(isWalkable(trianglesOnly, {0.5, 3.5}));
  CHECK(constrainedStep(trianglesOnly, {0.5f, 0.5f, 1.6f}, {0.0f, 2.0f}).y == doctest::Approx(0.5f));
}

TEST_CASE("the positions outside every view triangle: how many, and the farthest one's distance") {
  const ViewMesh mesh(kCorners, kXArm, lCorridors());
  // Inside, on an edge, on a corner, and up the y arm at 0.5, 1.5 and 3 m from the triangles.
  const std::vector<glm::dvec2> positions = {{3.0, 0.5}, {6.0, 0.5}, {0.0, 1.0}, {0.5, 1.5}, {0.5, 2.5}, {0.5, 4.0}};
  const UncoveredPositions uncovered = uncoveredPositions(mesh, positions);
  CHECK(uncovered.count == 3);
  CHECK(uncovered.farthest == doctest::Approx(3.0));
  CHECK(uncoveredPositions(mesh, std::span(positions).first(3)).count == 0);
}

TEST_CASE("N and B step to the nearest reference ahead and behind, within 60 degrees before 90") {
  // Vertices 0 (0,0), 1 (6,0), 2 (6,1), 3 (0,1).
  const ViewMesh mesh(kCorners, kXArm, lCorridors());
  const glm::dvec2 here(3.0, 0.7);
  CHECK(nearestVertexAhead(mesh, here, 0.0) == 2);    // east: (6,1) is nearer than (6,0)
  CHECK(nearestVertexAhead(mesh, here, 180.0) == 3);  // west: (0,1)
  CHECK(nearestVertexAhead(mesh, here, 340.0) == 2);  // 25.7 degrees off: still within 60
  // North: each vertex is more than 60 degrees off; within 90, (6,1) and
  // (0,1) are 84.3 degrees off and as near: the first.
  CHECK(nearestVertexAhead(mesh, here, 90.0) == 2);
  // From (6,0) looking west, (6,1) is nearest but 90 degrees off: the
  // vertex within 60 wins, and the walker's own vertex never counts.
  CHECK(nearestVertexAhead(mesh, {6.0, 0.0}, 180.0) == 0);
  CHECK(nearestVertexAhead(mesh, {6.0, 0.0}, 90.0) == 2);
  CHECK(nearestVertexAhead(mesh, {6.0, 0.0}, 300.0) == -1);  // nothing within 90 degrees
}

}  // namespace triwalk
