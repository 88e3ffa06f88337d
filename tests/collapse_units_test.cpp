// The decimator's units (core/selection/collapse/) on their own, with
// exact expected results on tiny meshes: the two boundary rules, the
// placements an edge tries, and the stop rule.

#include "core/geometry/view_mesh.h"
#include "core/selection/collapse/collapse_mesh.h"
#include "core/selection/collapse/collapse_rules.h"
#include "core/selection/collapse/placement_candidates.h"
#include "core/selection/collapse/stop_rule.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <algorithm>

namespace triwalk {

namespace {

double signedAreaOf(const std::vector<glm::dvec2>& positions, const Triangle& t) {
  const glm::dvec2 a = positions[size_t(t[0])], b = positions[size_t(t[1])], c = positions[size_t(t[2])];
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

}  // namespace

TEST_CASE("the two boundary rules: the paper's keeps a hull corner, the shrinking one lets it move along inside") {
  // 5 x 3 unit grid, sample (x, y) = 3 x + y: corner (0,0) = 0, (1,0) = 3.
  const std::vector<glm::dvec2> positions = testing::unitGrid(5, 3);
  const CollapseMesh mesh(ViewMesh::delaunay(positions, {}, "grid"));
  CollapsePlan plan;
  CHECK_FALSE(CollapseRules(mesh, BoundaryRule::Fixed, {}).planCollapse(0, 3, 3, PlacementKind::Second, plan));
  const CollapseRules shrinking(mesh, BoundaryRule::Shrinking, {});
  REQUIRE(shrinking.planCollapse(0, 3, 3, PlacementKind::Second, plan));
  // The collapse replaces the triangles of both ends; the corner's half
  // square beside the edge goes, so the covered area shrinks by 0.5, and
  // sample 0 is in no new triangle.
  double removed = 0.0, added = 0.0;
  for (int t : plan.removed) removed += signedAreaOf(positions, mesh.triangle(t));
  for (const Triangle& t : plan.added) {
    added += signedAreaOf(positions, t);
    CHECK(std::find(t.begin(), t.end(), 0) == t.end());
  }
  CHECK(removed - added == doctest::Approx(0.5));
  CHECK(plan.placement == 3);
  // A frozen sample (a tile's seam pass: outside the band) takes part in
  // no collapse, whatever the rule; the others go on.
  std::vector<char> frozen(positions.size(), 0);
  frozen[0] = 1;
  for (const BoundaryRule rule : {BoundaryRule::Fixed, BoundaryRule::Shrinking}) {
    const CollapseRules rules(mesh, rule, frozen);
    CHECK_FALSE(rules.planCollapse(0, 3, 3, PlacementKind::Second, plan));
    CHECK_FALSE(rules.planCollapse(0, 3, 0, PlacementKind::First, plan));
    CHECK(rules.planCollapse(6, 7, 6, PlacementKind::First, plan));
  }
}

TEST_CASE(
    "an edge tries either end, then the free sample nearest its midpoint, and with the one-ring every free sample "
    "inside the two ends' triangles") {
  // References: the corners of a 5 x 3 grid and its centre (2,1) = 7.
  const std::vector<glm::dvec2> positions = testing::unitGrid(5, 3);
  const std::vector<int> references = {0, 2, 7, 12, 14};
  const CollapseMesh mesh(ViewMesh::delaunay(positions, references, "grid"));
  NearestToMidpoint nearest;
  // Edge (0, 7): midpoint (1, 0.5), as near (1,0) = 3 as (1,1) = 4; the lower index.
  std::vector<PlacementCandidate> candidates = placementCandidates(mesh, 0, 7, false, nearest);
  REQUIRE(candidates.size() == 3);
  CHECK(candidates[0].sample == 0);
  CHECK(candidates[0].kind == PlacementKind::First);
  CHECK(candidates[1].sample == 7);
  CHECK(candidates[1].kind == PlacementKind::Second);
  CHECK(candidates[2].sample == 3);
  CHECK(candidates[2].kind == PlacementKind::Midpoint);
  CHECK(nearest.sample == 3);
  CHECK(nearest.distance == doctest::Approx(0.5));
  // The centre's triangles cover the grid: every free sample but the midpoint's, in index order.
  candidates = placementCandidates(mesh, 0, 7, true, nearest);
  std::vector<int> oneRing;
  for (size_t i = 3; i < candidates.size(); ++i) {
    CHECK(candidates[i].kind == PlacementKind::OneRing);
    oneRing.push_back(candidates[i].sample);
  }
  CHECK(oneRing == std::vector<int>{1, 4, 5, 6, 8, 9, 10, 11, 13});
}

TEST_CASE("the stop rule: a threshold refuses above it, a target is reached at it, and the time left follows both") {
  const StopRule threshold{1.85, 0};
  CHECK(threshold.refuses(1.86));
  CHECK_FALSE(threshold.refuses(1.85));
  CHECK_FALSE(threshold.reached(3));
  const StopRule target{0.0, 10};
  CHECK_FALSE(target.refuses(1e9));
  CHECK(target.reached(10));
  CHECK_FALSE(target.reached(11));
  CHECK(target.remainingCollapses(30, {}) == 20);
  // Under a threshold of 2 with the error rising 0.01 a collapse to 1.505:
  // 49.5 collapses more at that pace, the one that crosses included 50,
  // or the target's count if that comes first.
  std::vector<Collapse> log(40);
  for (size_t i = 0; i < log.size(); ++i) log[i].error = 1.505 - 0.01 * double(log.size() - 1 - i);
  const StopRule both{2.0, 10};
  CHECK(both.remainingCollapses(30, log) == 20);
  CHECK(both.remainingCollapses(200, log) == 50);
}

}  // namespace triwalk
