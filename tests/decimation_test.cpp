// Edge-collapse decimation on tiny hand-built meshes with exact expected
// behavior, and against a decimator rebuilt from scratch at every step.

#include "core/geometry/view_mesh.h"
#include "core/io/atomic_file.h"
#include "core/io/dataset.h"
#include "core/selection/edge_collapse_decimator.h"
#include "core/selection/selection.h"
#include "core/selection/selection_recipe.h"
#include "core/selection/triangle_error.h"
#include "core/support/errors.h"
#include "core/support/progress.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <tuple>

namespace triwalk {

namespace {

// Triangle errors from a formula: the area (bigger triangles reconstruct
// worse) plus a small per-triangle term so that costs never tie.
class SyntheticErrors final : public TriangleErrorSource {
public:
  explicit SyntheticErrors(std::vector<glm::dvec2> positions) : positions_(std::move(positions)) {}
  void computeErrors(std::span<const Triangle> triangles, std::span<double> errors) override {
    for (size_t i = 0; i < triangles.size(); ++i) {
      const Triangle& t = triangles[i];
      const glm::dvec2 a = positions_[size_t(t[0])], b = positions_[size_t(t[1])], c = positions_[size_t(t[2])];
      const double area = 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
      const Triangle sorted = sortedTriangle(t);
      errors[i] = area + 1e-4 * double((sorted[0] * 31 + sorted[1] * 17 + sorted[2] * 7) % 101);
      ++evaluations;
    }
  }
  int evaluations = 0;

private:
  std::vector<glm::dvec2> positions_;
};

// The paper's centroid cost, with a threshold (0: none) and a target.
DecimationOptions centroidOptions(double maxError = 0.0, int target = 0) {
  DecimationOptions options;
  options.maxError = maxError;
  options.targetSamples = target;
  options.cost = CollapseCost::Centroid;
  return options;
}

DecimationErrors fromTriangles(TriangleErrorSource& errors) { return {&errors, nullptr}; }

double signedArea(const ViewMesh& mesh) {
  double area = 0.0;
  for (const Triangle& t : mesh.triangles()) {
    const glm::dvec2 a = mesh.position(t[0]), b = mesh.position(t[1]), c = mesh.position(t[2]);
    area += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return area;
}

// Every triangle counter-clockwise, every edge in at most two triangles,
// and no edge twice in the same direction (a consistently oriented manifold).
void checkValidMesh(const ViewMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : mesh.triangles()) {
    CHECK(orientation(mesh.position(t[0]), mesh.position(t[1]), mesh.position(t[2])) > 0);
    for (int e = 0; e < 3; ++e) CHECK(++directed[{t[size_t(e)], t[size_t((e + 1) % 3)]}] == 1);
  }
}

}  // namespace

TEST_CASE("a collapse that violates the link condition is refused") {
  //  S3(0,8) ------------------- S2(8,8)
  //    |  \          X(4,5)    /   |
  //    |     v1(2,2)  Y(4,3)  v2(6,2)
  //  S0(0,0) ------------------- S1(8,0)
  // v1, v2 and X are pairwise adjacent around the inner vertex Y, but
  // (v1, v2, X) is not a triangle: collapsing v1-v2 would fold the mesh.
  enum { S0, S1, S2, S3, v1, v2, X, Y };
  const std::vector<glm::dvec2> positions = {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {2, 2}, {6, 2}, {4, 5}, {4, 3}};
  const std::vector<Triangle> triangles = {{v1, v2, Y}, {v2, X, Y}, {X, v1, Y},  {S0, S1, v2}, {S0, v2, v1},
                                           {S1, S2, v2}, {v2, S2, X}, {S2, S3, X}, {S3, v1, X},  {S3, S0, v1}};
  const ViewMesh mesh(positions, triangles);
  checkValidMesh(mesh);
  SyntheticErrors errors(positions);
  EdgeCollapseDecimator decimator(mesh, fromTriangles(errors), centroidOptions(0.0, 3));
  CHECK_FALSE(decimator.isValidCollapse(v1, v2, v1));
  CHECK_FALSE(decimator.isValidCollapse(v1, v2, v2));
  // The same kind of collapse where the link condition holds is allowed.
  CHECK(decimator.isValidCollapse(v1, Y, v1));
}

TEST_CASE("a collapse that flips a triangle is refused") {
  //        B(-1,1)       A(1,0.2)
  //             \  v1(0,0) ----- v2(2,0)
  //        C(-1,-1)      D(1,-0.2)
  // Moving v1 onto v2 turns (v1, A, B) into (v2, A, B), which is clockwise.
  enum { v1, v2, A, B, C, D };
  std::vector<glm::dvec2> positions = {{0, 0}, {2, 0}, {1, 0.2}, {-1, 1}, {-1, -1}, {1, -0.2}};
  const std::vector<Triangle> triangles = {{v1, v2, A}, {v1, A, B}, {v1, B, C}, {v1, C, D}, {v1, D, v2}};
  {
    const ViewMesh mesh(positions, triangles);
    checkValidMesh(mesh);
    SyntheticErrors errors(positions);
    EdgeCollapseDecimator decimator(mesh, fromTriangles(errors), centroidOptions(0.0, 3));
    CHECK_FALSE(decimator.isValidCollapse(v1, v2, v2));
  }
  // With A and D moved out to make the ring convex, the same collapse is fine.
  positions[A] = {1, 1};
  positions[D] = {1, -1};
  const ViewMesh convex(positions, triangles);
  SyntheticErrors errors(positions);
  EdgeCollapseDecimator decimator(convex, fromTriangles(errors), centroidOptions(0.0, 3));
  CHECK(decimator.isValidCollapse(v1, v2, v2));
}

TEST_CASE("boundary: corners never move, straight boundary vertices may go, the covered area never shrinks") {
  // 5 x 3 grid, decimated as far as validity allows.
  //   (0,2) . . . (4,2)
  //     .   . . .   .
  //   (0,0) . . . (4,0)
  const std::vector<glm::dvec2> positions = testing::unitGrid(5, 3);
  const ViewMesh initial = ViewMesh::delaunay(positions, {}, "grid");
  SyntheticErrors errors(positions);
  EdgeCollapseDecimator decimator(initial, fromTriangles(errors), centroidOptions(0.0, 3));
  while (decimator.step()) {
  }
  CHECK(decimator.stopReason() == StopReason::NoValidCollapse);
  const ViewMesh final = decimator.mesh();
  const std::set<int> kept(final.vertices().begin(), final.vertices().end());
  // Corners: (0,0) = 0, (0,2) = 2, (4,0) = 12, (4,2) = 14.
  CHECK(kept == std::set<int>{0, 2, 12, 14});
  CHECK(final.triangleCount() == 2);
  CHECK(signedArea(final) == doctest::Approx(8.0));

  // Boundary vertex (2,0) = 6 lies between (1,0) and (3,0): it may slide
  // along the boundary onto (3,0) = 9, but never inward onto (2,1) = 7.
  EdgeCollapseDecimator fresh(initial, fromTriangles(errors), centroidOptions(0.0, 3));
  CHECK(fresh.isValidCollapse(6, 9, 9));
  CHECK_FALSE(fresh.isValidCollapse(6, 7, 7));
  CHECK(fresh.isValidCollapse(6, 7, 6));
  // A corner never goes: (0,0) = 0 onto (1,0) = 3 is refused, the reverse is fine.
  CHECK_FALSE(fresh.isValidCollapse(0, 3, 3));
  CHECK(fresh.isValidCollapse(0, 3, 0));
}

TEST_CASE("replaying the log to any prefix gives a valid mesh, forward and backward") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(6, 5);
  const ViewMesh initial = ViewMesh::delaunay(positions, {}, "grid");
  SyntheticErrors errors(positions);
  EdgeCollapseDecimator decimator(initial, fromTriangles(errors), centroidOptions(0.0, 6));
  decimator.run();
  CHECK(decimator.stopReason() == StopReason::TargetReached);
  CHECK(decimator.vertexCount() == 6);
  const std::vector<Collapse>& log = decimator.log();
  REQUIRE(log.size() == 24);
  for (size_t steps = 0; steps <= log.size(); ++steps) {
    const ViewMesh prefix(positions, replayForward(initial.triangles(), log, steps));
    checkValidMesh(prefix);
    CHECK(prefix.vertexCount() == initial.vertexCount() - int(steps));
    CHECK(signedArea(prefix) == doctest::Approx(20.0));
  }
  CHECK(replayForward(initial.triangles(), log, log.size()) == decimator.mesh().triangles());
  CHECK(replayBackward(decimator.mesh().triangles(), log, log.size()) == initial.triangles());
}

TEST_CASE("stale heap entries are skipped: each collapse is the cheapest a fresh decimator finds") {
  // After every collapse, a decimator built from scratch on the current
  // mesh costs every edge anew; the incremental one, which re-costs only
  // the affected edges and skips stale heap entries, must agree. (Eager
  // re-costing: a lazy decimator may make a collapse that is not the
  // cheapest, from a stale cost, and is tested in refinement_test.cpp.)
  const std::vector<glm::dvec2> positions = testing::unitGrid(6, 5);
  const ViewMesh initial = ViewMesh::delaunay(positions, {}, "grid");
  SyntheticErrors errors(positions);
  DecimationOptions eager = centroidOptions(0.0, 5);
  eager.lazyRecosting = false;
  EdgeCollapseDecimator incremental(initial, fromTriangles(errors), eager);
  int steps = 0;
  while (true) {
    EdgeCollapseDecimator fresh(incremental.mesh(), fromTriangles(errors), centroidOptions(0.0, 5));
    const std::optional<Collapse> expected = fresh.peekNextCollapse();
    const std::optional<Collapse> next = incremental.peekNextCollapse();
    REQUIRE(expected.has_value() == next.has_value());
    if (!next || incremental.vertexCount() <= 5) break;
    CHECK(next->cost == expected->cost);
    CHECK(next->first == expected->first);
    CHECK(next->second == expected->second);
    CHECK(next->placement == expected->placement);
    CHECK(next->added == expected->added);
    REQUIRE(incremental.step());
    ++steps;
  }
  CHECK(steps == 25);
  CHECK(incremental.statistics().staleEntriesSkipped > 0);
}

TEST_CASE("the first costing of every edge counts its triangle errors and stops on Ctrl-C") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(12, 8);
  const ViewMesh initial = ViewMesh::delaunay(positions, {}, "grid");
  SyntheticErrors errors(positions);
  ProgressReporter costing("cost every edge", 0, true);
  EdgeCollapseDecimator decimator(initial, fromTriangles(errors), centroidOptions(1.85), &costing);
  CHECK(errors.evaluations > 64);  // more than one chunk
  CHECK(costing.done() == size_t(errors.evaluations));

  SyntheticErrors untouched(positions);
  ProgressReporter interrupted("cost every edge", 0, true);
  requestInterrupt();
  CHECK_THROWS_AS(EdgeCollapseDecimator(initial, fromTriangles(untouched), centroidOptions(1.85), &interrupted), Interrupted);
  clearInterrupt();
  CHECK(untouched.evaluations == 0);
}

TEST_CASE("edge cost: the area-weighted mean of the updated triangles' errors, or the paper's plain mean") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(4, 3);
  const ViewMesh initial = ViewMesh::delaunay(positions, {}, "grid");
  for (const bool weighted : {true, false}) {
    SyntheticErrors errors(positions);
    DecimationOptions options = centroidOptions(0.0, 3);
    options.areaWeightedCost = weighted;
    EdgeCollapseDecimator decimator(initial, fromTriangles(errors), options);
    // Take a few collapses so that the updated triangles differ in area.
    for (int i = 0; i < 4; ++i) REQUIRE(decimator.step());
    const std::optional<Collapse> next = decimator.peekNextCollapse();
    REQUIRE(next.has_value());
    std::vector<double> triangleErrors(next->added.size());
    errors.computeErrors(next->added, triangleErrors);
    double sum = 0.0, weightSum = 0.0, plainSum = 0.0;
    for (size_t i = 0; i < next->added.size(); ++i) {
      plainSum += triangleErrors[i];
      const Triangle& t = next->added[i];
      const glm::dvec2 a = positions[size_t(t[0])], b = positions[size_t(t[1])], c = positions[size_t(t[2])];
      const double weight = weighted ? 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) : 1.0;
      sum += weight * triangleErrors[i];
      weightSum += weight;
    }
    INFO("area weighted: " << weighted);
    CHECK(next->cost == doctest::Approx(sum / weightSum).epsilon(1e-12));
    // The updated triangles differ in area, so the two rules disagree here.
    if (weighted) CHECK(std::abs(sum / weightSum - plainSum / double(next->added.size())) > 1e-3);
  }
}

TEST_CASE("the triangle-error cache: every distinct triangle is computed once") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(6, 5);
  const ViewMesh initial = ViewMesh::delaunay(positions, {}, "grid");
  SyntheticErrors errors(positions);
  EdgeCollapseDecimator decimator(initial, fromTriangles(errors), centroidOptions(0.0, 5));
  decimator.run();
  const DecimationStatistics& statistics = decimator.statistics();
  CHECK(uint64_t(errors.evaluations) == statistics.errorsComputed);
  CHECK(statistics.cacheHits > statistics.errorsComputed);
}

TEST_CASE("point location walks to the containing triangle, and outside to the nearest") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(6, 5);
  const ViewMesh mesh = ViewMesh::delaunay(positions, {}, "grid");
  for (double x = 0.05; x < 5.0; x += 0.37) {
    for (double y = 0.05; y < 4.0; y += 0.41) {
      for (int hint : {-1, 0, mesh.triangleCount() - 1}) {
        const int t = mesh.locate({x, y}, hint);
        REQUIRE(t >= 0);
        CHECK(mesh.contains(t, {x, y}));
      }
    }
  }
  const int outside = mesh.locate({7.0, 2.0});
  CHECK(mesh.distanceToTriangle(outside, {7.0, 2.0}) == doctest::Approx(2.0));
}

TEST_CASE("outside every triangle, a position is served by the nearest triangle whose references see it") {
  // Two rooms, x in [0, 4] and [4.25, 8.25], joined by a doorway at y in [1, 2].
  const auto region = std::make_shared<const WalkableRegion>(
      std::vector<RegionPolygon>{{{{0, 0}, {4, 0}, {4, 1}, {4.25, 1}, {4.25, 0}, {8.25, 0}, {8.25, 3}, {4.25, 3}, {4.25, 2},
                                   {4, 2}, {4, 3}, {0, 3}},
                                  {}}},
      "two rooms");
  const std::vector<glm::dvec2> positions{{0.5, 1.5}, {1.5, 1.5}, {0.5, 2.5}, {4.5, 0.2}, {5.5, 0.2}, {4.5, 1.2}};
  const std::vector<Triangle> triangles{{0, 1, 2}, {3, 4, 5}};
  const glm::dvec2 corner(3.8, 0.3);  // in the first room, 0.7 m from the second room's triangle, behind the wall
  const ViewMesh withWalls(positions, triangles, region);
  const ViewMesh withoutWalls(positions, triangles);
  CHECK(withoutWalls.locate(corner) == 1);
  CHECK(withWalls.servingRank(1, corner).blind);
  CHECK(withWalls.locate(corner) == 0);
  CHECK_FALSE(withWalls.servingRank(0, corner).blind);
  // In the doorway both see it; the nearer serves.
  CHECK(withWalls.locate({4.1, 1.5}) == 1);
}

TEST_CASE("outside every triangle, locating takes the triangle that ranking every triangle takes") {
  // locate measures only the triangles whose bounds could come first; here
  // every answer is checked against the rule itself (the lowest-numbered
  // triangle that holds the point, else every triangle ranked by distance,
  // then sorted vertices: the first whose references see the point, else
  // the first), on meshes in pieces with holes, at lattice points where
  // triangles tie, and with a caller's remembered lines of sight.
  // Three rooms in a row, 0.25 m walls, each joined to the next by a doorway.
  const auto region = std::make_shared<const WalkableRegion>(
      std::vector<RegionPolygon>{{{{0, 0}, {4, 0}, {4, 1}, {4.25, 1}, {4.25, 0}, {8.25, 0}, {8.25, 2.5}, {8.5, 2.5},
                                   {8.5, 0}, {12.5, 0}, {12.5, 4}, {8.5, 4}, {8.5, 3.2}, {8.25, 3.2}, {8.25, 4},
                                   {4.25, 4}, {4.25, 2}, {4, 2}, {4, 4}, {0, 4}},
                                  {}}},
      "three rooms");
  std::vector<glm::dvec2> positions;
  for (double x = 0.25; x < 12.5; x += 0.5) {
    for (double y = 0.25; y < 4.0; y += 0.5) {
      if (region->contains({x, y})) positions.emplace_back(x, y);
    }
  }
  // Outside every triangle (-1 inside one).
  const auto byTheRule = [&](const ViewMesh& mesh, glm::dvec2 p) {
    for (int t = 0; t < mesh.triangleCount(); ++t) {
      if (mesh.contains(t, p)) return -1;
    }
    std::vector<std::tuple<double, Triangle, int>> ranked;
    for (int t = 0; t < mesh.triangleCount(); ++t) {
      ranked.emplace_back(mesh.distanceToTriangle(t, p), sortedTriangle(mesh.triangles()[size_t(t)]), t);
    }
    std::sort(ranked.begin(), ranked.end());
    for (const auto& [distance, vertices, t] : ranked) {
      if (!mesh.servingRank(t, p).blind) return t;
    }
    return std::get<2>(ranked.front());
  };
  std::mt19937 random(7);
  size_t outside = 0, blindNearest = 0, tiedNearest = 0;
  for (int round = 0; round < 6; ++round) {
    // A sparse random selection: its Delaunay triangles that stay inside
    // the rooms leave pieces, holes and rooms with no triangle at all.
    std::vector<int> chosen;
    for (int i = 0; i < int(positions.size()); ++i) {
      if (random() % 6 == 0) chosen.push_back(i);
    }
    const std::optional<ViewMesh> mesh = ViewMesh::tryDelaunay(positions, chosen, region.get());
    if (!mesh) continue;
    std::map<std::pair<int, int>, bool> remembered;
    for (double x = -0.5; x <= 13.0; x += 0.25) {
      for (double y = -0.5; y <= 4.5; y += 0.25) {
        const glm::dvec2 p(x, y);
        const int expected = byTheRule(*mesh, p);
        const int point = int(std::lround(4 * x)) * 1000 + int(std::lround(4 * y));
        const auto sees = [&](int v) {
          const auto [entry, added] = remembered.try_emplace({v, point}, false);
          if (added) entry->second = region->lineOfSight(positions[size_t(v)], p);
          return entry->second;
        };
        if (expected < 0) {  // inside: the walk's triangle, or one across a hole from it
          REQUIRE(mesh->contains(mesh->locate(p), p));
          REQUIRE(mesh->contains(mesh->locate(p, -1, sees), p));
        } else {
          REQUIRE(mesh->locate(p) == expected);
          REQUIRE(mesh->locate(p, -1, sees) == expected);
          ++outside;
          std::vector<double> distances;
          for (int t = 0; t < mesh->triangleCount(); ++t) distances.push_back(mesh->distanceToTriangle(t, p));
          const double nearest = *std::min_element(distances.begin(), distances.end());
          if (distances[size_t(expected)] > nearest) ++blindNearest;
          if (std::count(distances.begin(), distances.end(), nearest) > 1) ++tiedNearest;
        }
      }
    }
  }
  // The cases that matter were met: points outside, nearest triangles
  // behind a wall, and ties among the nearest.
  INFO(outside, " outside, ", blindNearest, " behind a wall, ", tiedNearest, " tied");
  CHECK(outside > 500);
  CHECK(blindNearest > 20);
  CHECK(tiedNearest > 20);
}

TEST_CASE("collinear and too few samples are refused with a clear error") {
  const std::vector<glm::dvec2> line = {{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  CHECK_THROWS_WITH_AS(ViewMesh::delaunay(line, {}, "manifest.json"),
                       doctest::Contains("manifest.json: the sample positions are collinear"), InputError);
  const std::vector<glm::dvec2> two = {{0, 0}, {1, 0}};
  CHECK_THROWS_WITH_AS(ViewMesh::delaunay(two, {}, "manifest.json"), doctest::Contains("at least 3 samples"), InputError);
}


TEST_CASE("a selection's recipe round-trips every setting: written, read and written again, byte for byte") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 64, 1);
  const Dataset dataset = Dataset::open(directory / "data");
  // Every setting away from its default.
  SelectionRecipe recipe;
  recipe.preset = "paper";
  TriangleErrorSettings& errors = recipe.errors;
  errors.width = 32;
  errors.stride = 2;
  errors.destinations = TriangleDestinations::Quadrature;
  errors.synthesis.warp.method = WarpMethod::Point;
  errors.synthesis.warp.stretchTest = StretchTest::DepthRatio;
  errors.synthesis.warp.grazingAngleDegrees = 7.5f;
  errors.synthesis.warp.maxDepthRatio = 1.3f;
  errors.synthesis.warp.mesh = SourceMesh::Simplified;
  errors.synthesis.warp.meshTolerancePixels = 0.5f;
  errors.synthesis.blend.epsilon = 0.07f;
  errors.synthesis.blend.minimumWeightDistance = 0.2f;
  errors.synthesis.blend.weights = BlendWeights::Distance;
  errors.synthesis.holes = HoleMode::Mark;
  errors.error.alpha = 5.0;
  errors.error.beta = 0.2;
  errors.error.delta = 10.0;
  errors.error.weighting = PixelWeighting::Uniform;
  DecimationOptions& decimation = recipe.selection.decimation;
  decimation.oneRingCandidates = true;
  decimation.cost = CollapseCost::Centroid;
  decimation.fixedBoundary = true;
  decimation.areaWeightedCost = false;
  decimation.pricedSamples = 8;
  decimation.lazyRecosting = false;
  decimation.maxError = 2.5;
  decimation.targetSamples = 5;
  recipe.selection.relativeError = 1.2;
  RefinementOptions& refinement = recipe.selection.refinement;
  refinement.radius = 0.3;
  refinement.maxExchanges = 4;
  refinement.screenedShare = 0.25;
  refinement.pricedSamples = 16;

  const nlohmann::json written = describeSelectionRecipe(recipe);
  const SelectionRecipe read = readSelectionRecipe(JsonObject(written, "selection.json", "settings"), dataset);
  CHECK(describeSelectionRecipe(read).dump() == written.dump());
  // Each field differs from the defaults' (so each was carried, not defaulted).
  const SelectionRecipe defaultRecipe;
  const nlohmann::json defaults = describeSelectionRecipe(defaultRecipe);
  CHECK(defaults.size() == written.size());
  for (const auto& [key, value] : written.items()) {
    INFO(key);
    CHECK(value != defaults.at(key));
  }
  // And a selection file keeps them: written with the selection, read back, written again.
  Selection selection;
  selection.method = "edge_collapse";
  const Triangle triangle = ViewMesh::delaunay(samplePositions(dataset), {}, "test").triangles().front();
  selection.samples = {triangle.begin(), triangle.end()};
  std::sort(selection.samples.begin(), selection.samples.end());
  selection.triangles = {triangle};
  selection.settings = written;
  writeSelection(directory / "a.json", selection, dataset);
  Selection again = readSelection(directory / "a.json", dataset);
  again.settings = describeSelectionRecipe(readSelectionRecipe(JsonObject(again.settings, "a.json", "settings"), dataset));
  writeSelection(directory / "b.json", again, dataset);
  CHECK(readTextFile(directory / "a.json") == readTextFile(directory / "b.json"));
}

TEST_CASE("selection.json round trip, and bad selections name the file and the problem") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 32, 1);
  const Dataset dataset = Dataset::open(directory / "data");
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  const ViewMesh initial = ViewMesh::delaunay(positions, {}, "test");
  SyntheticErrors errors(positions);
  EdgeCollapseDecimator decimator(initial, fromTriangles(errors), centroidOptions(0.0, 5));
  decimator.run();
  Selection selection;
  selection.method = "edge_collapse";
  selection.samples = decimator.mesh().vertices();
  selection.triangles = decimator.mesh().triangles();
  selection.initialTriangles = initial.triangles();
  selection.collapses = decimator.log();
  selection.stopReason = stopReasonName(decimator.stopReason());
  const std::filesystem::path file = directory / "selection.json";
  writeSelection(file, selection, dataset);
  const Selection loaded = readSelection(file, dataset);
  CHECK(loaded.samples == selection.samples);
  CHECK(loaded.triangles == selection.triangles);
  CHECK(loaded.initialTriangles == selection.initialTriangles);
  REQUIRE(loaded.collapses.size() == selection.collapses.size());
  CHECK(loaded.collapses.back().added == selection.collapses.back().added);
  CHECK(loaded.collapses.back().cost == selection.collapses.back().cost);
  CHECK_FALSE(loaded.errors.has_value());
  CHECK_FALSE(loaded.decimation.has_value());

  auto edit = [&](const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json document = nlohmann::json::parse(readTextFile(file));
    change(document);
    writeTextFileAtomically(directory / "bad.json", document.dump());
    return directory / "bad.json";
  };
  const std::string bad = (directory / "bad.json").string();
  testing::requireInputError([&] { readSelection(edit([](nlohmann::json& d) { d["samples"][0] = 999; }), dataset); }, bad,
                             "sample id 999 is not in");
  testing::requireInputError(
      [&] {
        readSelection(edit([](nlohmann::json& d) { std::swap(d["triangles"][0][1], d["triangles"][0][2]); }), dataset);
      },
      bad, "not counter-clockwise");
  testing::requireInputError(
      [&] { readSelection(edit([](nlohmann::json& d) { d["collapses"].erase(d["collapses"].begin()); }), dataset); }, bad,
      "removes a triangle the mesh does not have");
  testing::requireInputError([&] { readSelection(edit([](nlohmann::json& d) { d["version"] = 2; }), dataset); }, bad,
                             "unknown selection version 2");
  // A selection of another data set (here: another fingerprint) is named as such.
  testing::requireInputError(
      [&] { readSelection(edit([](nlohmann::json& d) { d["dataset"]["fingerprint"] = "0123456789abcdef"; }), dataset); }, bad,
      "other sample ids or positions (fingerprint 0123456789abcdef, the data set's " + dataset.fingerprint() +
          "); run decimate on this data set again");
  testing::requireInputError(
      [&] {
        readSelection(edit([](nlohmann::json& d) { d["dataset"] = {{"fingerprint", "0123456789abcdef"}, {"scene", "x"}}; }),
                      dataset);
      },
      bad, "made for another data set (scene 'x', 0 samples)");
  // The same positions captured at another width take the selection; other
  // positions (one path more) do not.
  testing::writeAnalyticDataset(directory / "wider", 4, 3, 64, 1);
  CHECK(readSelection(file, Dataset::open(directory / "wider")).samples == selection.samples);
  testing::writeAnalyticDataset(directory / "longer", 4, 4, 32, 1);
  testing::requireInputError([&] { readSelection(file, Dataset::open(directory / "longer")); }, file.string(),
                             "made for another data set");

  // The errors the decimation read, which the viewer goes on with: a file
  // that names only the lattice gets decimate's defaults for the rest.
  const Selection lattice = readSelection(edit([](nlohmann::json& d) {
                                            d["settings"] = {{"error_width", 16}, {"error_stride", 4}};
                                          }),
                                          dataset);
  REQUIRE(lattice.errors.has_value());
  CHECK(lattice.errors->width == 16);
  CHECK(lattice.errors->stride == 4);
  CHECK(lattice.errors->synthesis.warp.mesh == kSelectionSourceMesh);
  CHECK(lattice.errors->synthesis.blend.weights == kSelectionBlendWeights);
  CHECK(lattice.errors->synthesis.holes == kDefaultErrorHoles);
  const Selection older = readSelection(edit([](nlohmann::json& d) { d["settings"] = {{"holes", "mark"}}; }), dataset);
  REQUIRE(older.errors.has_value());
  CHECK(older.errors->width == errorWidthFor(dataset, 0));
  CHECK(older.errors->stride == 1);
  CHECK(older.errors->synthesis.holes == HoleMode::Mark);

  // Every option away from decimate's default comes back as it was made.
  TriangleErrorSettings madeErrors;
  madeErrors.width = 16;
  madeErrors.stride = 2;
  madeErrors.destinations = TriangleDestinations::Quadrature;
  madeErrors.synthesis.warp = {.method = WarpMethod::Point, .stretchTest = StretchTest::DepthRatio, .grazingAngleDegrees = 7.5f,
                         .maxDepthRatio = 1.5f, .mesh = SourceMesh::Grid, .meshTolerancePixels = 0.75f};
  madeErrors.synthesis.blend = {.epsilon = 0.125f, .minimumWeightDistance = 0.25f, .weights = BlendWeights::Reliability};
  madeErrors.synthesis.holes = HoleMode::Mark;
  madeErrors.error = {.alpha = 2.0, .beta = 0.5, .delta = 9.0, .weighting = PixelWeighting::Uniform};
  const Selection remade = readSelection(edit([&](nlohmann::json& d) { d["settings"] = describeSelectionErrors(madeErrors); }), dataset);
  REQUIRE(remade.errors.has_value());
  const TriangleErrorSettings& read = *remade.errors;
  CHECK(read.width == 16);
  CHECK(read.stride == 2);
  CHECK(read.destinations == TriangleDestinations::Quadrature);
  CHECK(read.synthesis.warp.method == WarpMethod::Point);
  CHECK(read.synthesis.warp.stretchTest == StretchTest::DepthRatio);
  CHECK(read.synthesis.warp.grazingAngleDegrees == 7.5f);
  CHECK(read.synthesis.warp.maxDepthRatio == 1.5f);
  CHECK(read.synthesis.warp.mesh == SourceMesh::Grid);
  CHECK(read.synthesis.warp.meshTolerancePixels == 0.75f);
  CHECK(read.synthesis.blend == madeErrors.synthesis.blend);
  CHECK(read.synthesis.holes == HoleMode::Mark);
  CHECK(read.error.alpha == 2.0);
  CHECK(read.error.beta == 0.5);
  CHECK(read.error.delta == 9.0);
  CHECK(read.error.weighting == PixelWeighting::Uniform);

  // Float options are written as people write them, and read back as the same floats.
  TriangleErrorSettings defaults;
  defaults.width = 32;
  const nlohmann::json written = describeSelectionErrors(defaults);
  CHECK(written.at("depth_ratio").dump() == "1.15");
  CHECK(written.at("epsilon").dump() == "0.05");
  const Selection asDefaults = readSelection(edit([&](nlohmann::json& d) { d["settings"] = written; }), dataset);
  REQUIRE(asDefaults.errors.has_value());
  CHECK(asDefaults.errors->synthesis.warp.maxDepthRatio == defaults.synthesis.warp.maxDepthRatio);
  CHECK(asDefaults.errors->synthesis.blend == defaults.synthesis.blend);

  auto refused = [&](nlohmann::json settings, const std::string& problem) {
    testing::requireInputError([&] { readSelection(edit([&](nlohmann::json& d) { d["settings"] = settings; }), dataset); },
                               bad, problem);
  };
  refused({{"error_width", 24}}, "settings: error_width 24 does not divide the data set's width 32");
  refused({{"error_stride", 3}}, "settings: error_stride: must be a power of two dividing the error panorama's height (16), not 3");
  refused({{"error_width", 4}, {"error_stride", 4}}, "settings: error_stride: must be a power of two dividing the error panorama's height (2), not 4");
  refused({{"error_stride", 2.5}}, "field 'settings.error_stride' is not an integer");
  refused({{"error_stride", 2}, {"holes", "fill"}}, "settings: error_stride: a lattice of pixels cannot be hole-filled: use it with holes black or mark");
  refused({{"source_mesh", "quads"}}, "settings: unknown source mesh 'quads'");
  refused({{"destinations", "corners"}}, "settings: unknown choice 'corners'");
  refused({{"stretch_test", "angle"}}, "settings: unknown stretch test 'angle'");
  refused({{"blend_weights", "equal"}}, "settings: unknown blend weights 'equal'");
  refused({{"holes", "none"}}, "settings: unknown hole mode 'none'");
  refused({{"pixel_weighting", "area"}}, "settings: unknown weighting 'area'");
  refused({{"grazing_angle", 95}}, "settings: grazing_angle must be from 0 to 89, not 95");
  refused({{"depth_ratio", 0.5}}, "settings: depth_ratio must be from 1 to 1000, not 0.5");
  refused({{"mesh_tolerance", -1}}, "settings: mesh_tolerance must be from 0 to 8, not -1");
  refused({{"epsilon", 11}}, "settings: epsilon must be from 0.0001 to 10, not 11");
  refused({{"epsilon", 0}}, "settings: epsilon must be from 0.0001 to 10, not 0");
  refused({{"alpha", 1e300}}, "settings: alpha must be from 0 to 1e+06, not 1e+300");
  refused({{"min_weight_distance", 0}}, "settings: min_weight_distance must be from 0.001 to 10000, not 0");
  refused({{"delta", -2}}, "settings: delta must be from 0 to 255, not -2");
  refused({{"point_warp", "yes"}}, "field 'settings.point_warp' is not true or false");
  refused({{"alpha", "ten"}}, "field 'settings.alpha' is not a number");

  // The threshold it stopped at, where "run to error" starts in the viewer.
  const Selection thresholds = readSelection(edit([](nlohmann::json& d) {
                                               d["settings"] = {{"max_error", 1.5}, {"relative_error", 1.25}};
                                             }),
                                             dataset);
  CHECK(thresholds.maxError == 1.5);
  CHECK(thresholds.relativeError == 1.25);
  CHECK(lattice.maxError == 0.0);
  refused({{"max_error", -1}}, "settings: max_error must be 0 (none) or from 1e-09 to 1e+09, not -1");
  refused({{"relative_error", 1e300}}, "settings: relative_error must be 0 (none) or from 1e-06 to 1e+06, not 1e+300");
  refused({{"relative_error", "auto"}}, "field 'settings.relative_error' is not a number");

  // The collapse options, every one away from its default, and a file
  // that predates some of them.
  DecimationOptions made;
  made.oneRingCandidates = true;
  made.cost = CollapseCost::Centroid;
  made.fixedBoundary = true;
  made.areaWeightedCost = false;
  made.pricedSamples = 7;
  made.lazyRecosting = false;
  const Selection options = readSelection(edit([&](nlohmann::json& d) { d["settings"] = describeDecimationOptions(made); }), dataset);
  REQUIRE(options.decimation.has_value());
  CHECK(options.decimation->oneRingCandidates);
  CHECK(options.decimation->cost == CollapseCost::Centroid);
  CHECK(options.decimation->fixedBoundary);
  CHECK_FALSE(options.decimation->areaWeightedCost);
  CHECK(options.decimation->pricedSamples == 7);
  CHECK_FALSE(options.decimation->lazyRecosting);
  const Selection costOnly = readSelection(edit([](nlohmann::json& d) { d["settings"] = {{"cost", "served-samples"}}; }), dataset);
  REQUIRE(costOnly.decimation.has_value());
  CHECK_FALSE(costOnly.errors.has_value());
  CHECK(costOnly.decimation->pricedSamples == DecimationOptions{}.pricedSamples);
  CHECK(costOnly.decimation->lazyRecosting == DecimationOptions{}.lazyRecosting);
  testing::requireInputError(
      [&] { readSelection(edit([](nlohmann::json& d) { d["settings"] = {{"cost", "median"}}; }), dataset); }, bad,
      "settings: unknown cost 'median'");
  testing::requireInputError(
      [&] {
        readSelection(edit([](nlohmann::json& d) { d["settings"] = {{"cost", "centroid"}, {"priced_samples", -1}}; }),
                      dataset);
      },
      bad, "settings: priced_samples must not be negative");
  testing::requireInputError(
      [&] {
        readSelection(edit([](nlohmann::json& d) { d["settings"] = {{"cost", "centroid"}, {"one_ring", "yes"}}; }), dataset);
      },
      bad, "field 'settings.one_ring' is not true or false");
  testing::requireInputError(
      [&] {
        readSelection(edit([](nlohmann::json& d) { d["settings"] = {{"cost", "centroid"}, {"recosting", "soon"}}; }),
                      dataset);
      },
      bad, "settings: unknown recosting 'soon'");
  std::ofstream(directory / "broken.json") << "{\"format\": ";
  testing::requireInputError([&] { readSelection(directory / "broken.json", dataset); }, "broken.json", "malformed JSON");
}

}  // namespace triwalk
