// The refinement after decimation: references move to nearby free samples
// while that lowers the mean error over the dense samples, on tiny grids
// with errors whose best answer is known, and on a captured data set. And
// how both serve the samples outside the mesh: as eval and the viewer do.

#include "core/geometry/view_mesh.h"
#include "core/image/color.h"
#include "core/io/atomic_file.h"
#include "core/io/dataset.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection.h"
#include "core/selection/selection_refinement.h"
#include "core/selection/triangle_error.h"
#include "core/support/errors.h"
#include "core/support/progress.h"
#include "core/synthesis/blend.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

namespace triwalk {

namespace {

// Errors from a formula of the destination and the three references.
class FormulaErrors final : public ReconstructionErrorSource {
public:
  using Formula = std::function<double(const Triangle& references, int destination)>;
  explicit FormulaErrors(Formula formula) : formula_(std::move(formula)) {}
  void computeReconstructionErrors(std::span<const SampleReconstruction> requests, std::span<double> errors) override {
    for (size_t i = 0; i < requests.size(); ++i) errors[i] = formula_(requests[i].references, requests[i].destination);
    computed += int(requests.size());
  }
  int computed = 0;

private:
  Formula formula_;
};

// Errors that grow with the distance from each of the three references to
// the destination, and jump where a wall stands between them.
FormulaErrors::Formula distanceAndSightErrors(const std::vector<glm::dvec2>& positions, const WalkableRegion& region) {
  return [&positions, &region](const Triangle& t, int destination) {
    double error = 0.0;
    for (int v : t) {
      const glm::dvec2 a = positions[size_t(v)], b = positions[size_t(destination)];
      error += glm::length(a - b) + (region.lineOfSight(a, b) ? 0.0 : 10.0);
    }
    return error;
  };
}

// The local moves alone: within 1.5 m, up to 20 passes, no exchanges.
const RefinementOptions kLocalOnly{1.5, 20, {}, nullptr, 0};

bool contains(const Triangle& t, int sample) {
  return std::find(t.begin(), t.end(), sample) != t.end();
}

// The objective recomputed from scratch: every sample that is not a
// reference, reconstructed from the triangle around it.
double meanError(const ViewMesh& mesh, const FormulaErrors::Formula& formula) {
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < int(mesh.positions().size()); ++i) {
    if (std::binary_search(mesh.vertices().begin(), mesh.vertices().end(), i)) continue;
    sum += formula(sortedTriangle(mesh.triangles()[size_t(mesh.locate(mesh.position(i)))]), i);
    ++count;
  }
  return sum / double(count);
}

}  // namespace

TEST_CASE("a reference that spoils every triangle it is in moves away to the lowest free neighbour") {
  //   4  7 11 15     a 4 x 4 grid, 1 m apart, numbered column by column
  //   3  6 10 14     except that sample 0 is the one at (1, 1);
  //   2  0  9 13     references: the corners 1, 4, 12, 15 and sample 0,
  //   1  5  8 12     whose panorama is bad: every reconstruction that uses
  //                  it costs 11, every other costs 1.
  std::vector<glm::dvec2> positions = {{1, 1}};
  for (const glm::dvec2& p : testing::unitGrid(4, 4)) {
    if (p != glm::dvec2(1, 1)) positions.push_back(p);
  }
  const FormulaErrors::Formula formula = [](const Triangle& t, int) { return contains(t, 0) ? 11.0 : 1.0; };
  FormulaErrors errors(formula);
  const std::vector<int> references = {0, 1, 4, 12, 15};
  const ViewMesh start = ViewMesh::delaunay(positions, references, "test");
  const RefinementResult result = refineSelection(positions, start.triangles(), errors, kLocalOnly);

  // Sample 0 is in every triangle of the start, so every sample costs 11.
  CHECK(result.objectiveBefore == 11.0);
  // Sample 0 is examined first; moving it to any free neighbour removes
  // the bad panorama, so those moves tie at 1 and the lowest index (2, at
  // (0, 1)) wins; nothing can go below 1 after that.
  REQUIRE(result.moves.size() == 1);
  CHECK(result.moves[0].kind == PlacementKind::Relocation);
  CHECK(result.moves[0].first == 0);
  CHECK(result.moves[0].placement == 2);
  CHECK(result.moves[0].cost == 1.0);
  CHECK(result.objectiveAfter == 1.0);
  const ViewMesh final(positions, result.triangles);
  CHECK(final.vertices() == std::vector<int>{1, 2, 4, 12, 15});
  CHECK(final.triangles() == ViewMesh::delaunay(positions, final.vertices(), "test").triangles());
}

TEST_CASE("refinement lowers the mean error, logs moves that replay to the result, and keeps the sample count") {
  // 8 x 5 grid; a reconstruction costs the distance from the destination to
  // the nearest of its references, so references crowded into one corner
  // must spread out.
  const std::vector<glm::dvec2> positions = testing::unitGrid(8, 5);
  const FormulaErrors::Formula formula = [&](const Triangle& t, int destination) {
    double nearest = 1e9;
    for (int r : t) nearest = std::min(nearest, glm::length(positions[size_t(r)] - positions[size_t(destination)]));
    return nearest;
  };
  FormulaErrors errors(formula);
  const std::vector<int> references = {0, 1, 5, 6, 2};  // (0,0) (0,1) (1,0) (1,1) (0,2)
  const ViewMesh start = ViewMesh::delaunay(positions, references, "test");
  const RefinementResult result = refineSelection(positions, start.triangles(), errors, kLocalOnly);

  REQUIRE(result.moves.size() >= 3);
  CHECK(result.objectiveAfter < 0.6 * result.objectiveBefore);
  const ViewMesh final(positions, result.triangles);
  CHECK(final.vertexCount() == 5);
  CHECK(result.objectiveAfter == doctest::Approx(meanError(final, formula)));
  // Each move lowers the objective; replaying them from the start triangles
  // passes through Delaunay meshes of the moved references to the result.
  double previous = result.objectiveBefore;
  std::vector<Triangle> replayed = start.triangles();
  std::vector<int> current = references;
  std::sort(current.begin(), current.end());
  for (size_t i = 0; i < result.moves.size(); ++i) {
    const Collapse& move = result.moves[i];
    CHECK(move.cost < previous);
    previous = move.cost;
    CHECK(glm::length(positions[size_t(move.placement)] - positions[size_t(move.first)]) <= 1.5);
    std::replace(current.begin(), current.end(), move.first, move.placement);
    std::sort(current.begin(), current.end());
    replayed = replayForward(replayed, std::span(result.moves).subspan(i, 1), 1);
    CHECK(replayed == ViewMesh::delaunay(positions, current, "test").triangles());
    CHECK(samplesAfter(5, result.moves, i + 1) == 5);
  }
  CHECK(replayed == result.triangles);
  CHECK(replayBackward(result.triangles, result.moves, result.moves.size()) == start.triangles());
  // A second refinement from the result finds nothing to move, in one pass.
  const RefinementResult again = refineSelection(positions, final.triangles(), errors, kLocalOnly);
  CHECK(again.moves.empty());
  CHECK(again.passes == 1);
}

TEST_CASE("an exchange moves a reference where no local move reaches: across a gap") {
  // Two 4 x 4 grids of samples 1 m apart, x 0..3 and x 8..11, 5 m between
  // them; a reconstruction costs the distance from the destination to the
  // nearest of its references. References: the corners of the left grid
  // and two inside it, and the right grid's two far corners, so the right
  // grid is served from 3 to 8 m away. No local move (1.5 m) crosses the
  // gap; an exchange takes a left reference to the right grid.
  std::vector<glm::dvec2> positions;
  for (const double left : {0.0, 8.0}) {
    for (int x = 0; x < 4; ++x) {
      for (int y = 0; y < 4; ++y) positions.emplace_back(left + x, double(y));
    }
  }
  const FormulaErrors::Formula formula = [&](const Triangle& t, int destination) {
    double nearest = 1e9;
    for (int r : t) nearest = std::min(nearest, glm::length(positions[size_t(r)] - positions[size_t(destination)]));
    return nearest;
  };
  auto at = [](int x, int y) { return x < 8 ? x * 4 + y : 16 + (x - 8) * 4 + y; };
  const std::vector<int> references = {at(0, 0), at(0, 3), at(3, 0),  at(3, 3),
                                       at(1, 1), at(2, 2), at(11, 0), at(11, 3)};
  const ViewMesh start = ViewMesh::delaunay(positions, references, "test");
  FormulaErrors withExchanges(formula), localOnly(formula);
  const RefinementResult exchanged =
      refineSelection(positions, start.triangles(), withExchanges, {1.5, 20, {}, nullptr, {}});
  const RefinementResult local = refineSelection(positions, start.triangles(), localOnly, kLocalOnly);

  REQUIRE(exchanged.exchanges >= 1);
  // Some move took a reference from the left grid to the right one.
  CHECK(std::any_of(exchanged.moves.begin(), exchanged.moves.end(), [&](const Collapse& move) {
    return positions[size_t(move.first)].x < 4.0 && positions[size_t(move.placement)].x > 7.0;
  }));
  CHECK(std::none_of(local.moves.begin(), local.moves.end(), [&](const Collapse& move) {
    return positions[size_t(move.first)].x < 4.0 && positions[size_t(move.placement)].x > 7.0;
  }));
  // The objective falls with every move, ends where it says, and below
  // where local moves alone end.
  double previous = exchanged.objectiveBefore;
  for (const Collapse& move : exchanged.moves) {
    CHECK(move.cost < previous);
    previous = move.cost;
  }
  const ViewMesh final(positions, exchanged.triangles);
  CHECK(final.vertexCount() == 8);
  CHECK(exchanged.objectiveAfter == doctest::Approx(meanError(final, formula)));
  CHECK(exchanged.objectiveAfter < 0.9 * local.objectiveAfter);
  // The log replays from the start to the result.
  CHECK(replayForward(start.triangles(), exchanged.moves, exchanged.moves.size()) == exchanged.triangles);
  // The exchange searches' share of the errors is counted apart.
  CHECK(local.exchangeSearchErrors == 0);
  CHECK(exchanged.exchangeSearchErrors > 0);
  CHECK(exchanged.exchangeSearchErrors < exchanged.errorsComputed);
  // No more exchanges than asked.
  FormulaErrors capped(formula);
  CHECK(refineSelection(positions, start.triangles(), capped, {1.5, 20, {}, nullptr, 0}).exchanges == 0);
}

TEST_CASE("refinement starts from the Delaunay mesh of a decimated mesh's references, and is never worse than it") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(8, 5);
  const std::vector<int> references = {0, 1, 5, 6, 2, 39};  // crowded at (0,0)-(1,1), and the far corner (7, 4)
  const ViewMesh delaunay = ViewMesh::delaunay(positions, references, "test");
  // A mesh that is not Delaunay: the Delaunay one without a triangle on
  // its boundary, as a decimation whose boundary shrank leaves.
  int dropped = -1;
  for (int t = 0; t < delaunay.triangleCount() && dropped < 0; ++t) {
    const bool onBoundary =
        delaunay.neighbour(t, 0) < 0 || delaunay.neighbour(t, 1) < 0 || delaunay.neighbour(t, 2) < 0;
    const Triangle& triangle = delaunay.triangles()[size_t(t)];
    const bool keepsVertices =
        std::all_of(triangle.begin(), triangle.end(), [&](int v) { return delaunay.trianglesAround(v).size() > 1; });
    if (onBoundary && keepsVertices) dropped = t;
  }
  REQUIRE(dropped >= 0);
  std::vector<Triangle> decimated = delaunay.triangles();
  decimated.erase(decimated.begin() + dropped);

  SUBCASE("moves are made from the Delaunay mesh and the log replays from the decimated one") {
    const FormulaErrors::Formula formula = [&](const Triangle& t, int destination) {
      double nearest = 1e9;
      for (int r : t) nearest = std::min(nearest, glm::length(positions[size_t(r)] - positions[size_t(destination)]));
      return nearest;
    };
    FormulaErrors errors(formula);
    const RefinementResult result = refineSelection(positions, decimated, errors, kLocalOnly);
    REQUIRE(!result.moves.empty());
    CHECK(result.objectiveAfter < result.objectiveBefore);
    CHECK(replayForward(decimated, result.moves, result.moves.size()) == result.triangles);
    CHECK(replayBackward(result.triangles, result.moves, result.moves.size()) == decimated);
  }
  SUBCASE("when no move beats the decimated mesh, it is kept as it was") {
    // Its own triangles reconstruct perfectly, any other triangle badly.
    const FormulaErrors::Formula formula = [&](const Triangle& t, int) {
      const bool own = std::any_of(decimated.begin(), decimated.end(),
                                   [&](const Triangle& d) { return sortedTriangle(d) == sortedTriangle(t); });
      return own ? 0.0 : 5.0;
    };
    FormulaErrors errors(formula);
    const RefinementResult result = refineSelection(positions, decimated, errors, {1.5, 20, {}, nullptr, {}});
    CHECK(result.moves.empty());
    CHECK(result.exchanges == 0);
    CHECK(result.triangles == decimated);
    CHECK(result.objectiveBefore == 0.0);
    CHECK(result.objectiveAfter == 0.0);
  }
}

TEST_CASE("samples of weight 0 are not judged: a margin no move can serve better does not decide whether moves are kept") {
  // A tile's situation (core/selection/tiled_selection.cpp, runTile): an
  // 8 x 5 grid whose right column (x = 7) is margin, frozen, with two
  // frozen references at its ends; the core's four references crowd the
  // corner (0, 0)-(1, 1). The decimation left the margin's triangle out,
  // so its three samples are served by the triangles beside it, well;
  // every other triangle serves them badly (1000), and the Delaunay mesh
  // the refinement restarts from has that triangle back. The core's
  // samples cost the distance to the nearest reference of their triangle.
  const std::vector<glm::dvec2> positions = testing::unitGrid(8, 5);  // sample x * 5 + y
  std::vector<char> margin(positions.size(), 0);
  for (size_t i = 0; i < positions.size(); ++i) margin[i] = positions[i].x == 7.0 ? 1 : 0;
  const std::vector<int> references = {0, 1, 5, 6, 35, 39};
  const ViewMesh delaunay = ViewMesh::delaunay(positions, references, "test");
  const int marginTriangle = delaunay.locate(positions[37]);
  std::vector<Triangle> decimated = delaunay.triangles();
  decimated.erase(decimated.begin() + marginTriangle);
  const ViewMesh start(positions, decimated);
  REQUIRE(start.vertexCount() == 6);  // every reference still has a triangle

  int marginAsked = 0;
  const FormulaErrors::Formula formula = [&](const Triangle& t, int destination) {
    if (margin[size_t(destination)]) {
      ++marginAsked;
      const bool served = std::any_of(decimated.begin(), decimated.end(),
                                      [&](const Triangle& d) { return sortedTriangle(d) == sortedTriangle(t); });
      return served ? 0.0 : 1000.0;
    }
    double nearest = 1e9;
    for (int r : t) nearest = std::min(nearest, glm::length(positions[size_t(r)] - positions[size_t(destination)]));
    return nearest;
  };
  RefinementOptions options = kLocalOnly;
  options.frozen = margin;

  SUBCASE("judged, the margin's samples make every move from the Delaunay restart lose: nothing is kept") {
    FormulaErrors errors(formula);
    const RefinementResult result = refineSelection(positions, decimated, errors, options);
    CHECK(result.moves.empty());
    CHECK(result.triangles == decimated);
  }
  SUBCASE("weighted 0, the core's samples alone decide: the crowded references spread out") {
    options.sampleWeights.assign(positions.size(), 1.0);
    for (size_t i = 0; i < positions.size(); ++i) {
      if (margin[i]) options.sampleWeights[i] = 0.0;
    }
    FormulaErrors errors(formula);
    const RefinementResult result = refineSelection(positions, decimated, errors, options);
    REQUIRE(result.moves.size() >= 2);
    // The objective is the mean over the core's samples that are not
    // references, and the margin's errors were never asked for.
    CHECK(marginAsked == 0);
    double sum = 0.0;
    int count = 0;
    for (int i = 0; i < int(positions.size()); ++i) {
      if (margin[size_t(i)] || std::binary_search(references.begin(), references.end(), i)) continue;
      sum += formula(sortedTriangle(decimated[size_t(start.locate(positions[size_t(i)]))]), i);
      ++count;
    }
    CHECK(result.objectiveBefore == doctest::Approx(sum / double(count)));
    CHECK(result.objectiveAfter < 0.8 * result.objectiveBefore);
    for (const Collapse& move : result.moves) CHECK(!margin[size_t(move.placement)]);
  }
}

TEST_CASE("exchange candidates are free samples spread over the area") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(10, 10);  // 1 m apart
  const std::vector<int> references = {0, 11, 22};
  const std::vector<int> candidates = exchangeCandidates(positions, references);
  for (size_t i = 0; i < candidates.size(); ++i) {
    CHECK(std::find(references.begin(), references.end(), candidates[i]) == references.end());
    for (size_t j = 0; j < i; ++j)
      CHECK(glm::length(positions[size_t(candidates[i])] - positions[size_t(candidates[j])]) >= 1.5);
  }
  // Every free sample has a candidate within two spacings: none of the
  // area is left out.
  for (int s = 0; s < 100; ++s) {
    double nearest = 1e9;
    for (int c : candidates) nearest = std::min(nearest, glm::length(positions[size_t(c)] - positions[size_t(s)]));
    CHECK(nearest < 2.0);
  }
  CHECK(candidates.size() < 40);  // far fewer than the 97 free samples
}

TEST_CASE("refinement with radius 0 changes nothing, and Ctrl-C stops it") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(6, 4);
  FormulaErrors errors(
      [](const Triangle& t, int destination) { return double((t[0] + t[1] + t[2] + destination) % 7); });
  const std::vector<int> references = {0, 3, 20, 23, 9};
  const ViewMesh start = ViewMesh::delaunay(positions, references, "test");
  const RefinementResult unchanged = refineSelection(positions, start.triangles(), errors, {0.0, 8, {}, nullptr, {}});
  CHECK(unchanged.moves.empty());
  CHECK(unchanged.triangles == start.triangles());
  CHECK(unchanged.objectiveAfter == unchanged.objectiveBefore);

  requestInterrupt();
  CHECK_THROWS_AS(refineSelection(positions, start.triangles(), errors, {1.5, 8, {}, nullptr, {}}), Interrupted);
  clearInterrupt();
}

TEST_CASE("sample counts along a log with relocations, and where a count is last reached") {
  std::vector<Collapse> log(4);
  log[0].kind = PlacementKind::Midpoint;
  log[1].kind = PlacementKind::First;
  log[2].kind = PlacementKind::Relocation;
  log[3].kind = PlacementKind::Relocation;
  CHECK(samplesAfter(10, log, 0) == 10);
  CHECK(samplesAfter(10, log, 2) == 8);
  CHECK(samplesAfter(10, log, 4) == 8);
  CHECK(lastStepWithSamples(10, log, 10) == 0u);
  CHECK(lastStepWithSamples(10, log, 9) == 1u);
  CHECK(lastStepWithSamples(10, log, 8) == 4u);  // the refinement is part of the final count
  CHECK(!lastStepWithSamples(10, log, 7).has_value());
}

// Decimation's own determinism is checked here too: the collapses come first
// in the log compared.
TEST_CASE("the default refinement radius reaches a sample's eight nearest neighbours, whatever the spacing") {
  // A square lattice: the diagonal neighbours. A lattice of 0.31 x 0.75 m
  // rows: the diagonals too, not just the two neighbours along a row (what
  // an absolute 0.5 m gave), and a 1.46 m lattice gets 1.47 m, not nothing.
  auto lattice = [](double dx, double dy) {
    std::vector<glm::dvec2> points;
    for (int x = 0; x < 20; ++x) {
      for (int y = 0; y < 12; ++y) points.emplace_back(dx * x, dy * y);
    }
    return points;
  };
  CHECK(neighbourhoodRadius(lattice(1.0, 1.0)) == doctest::Approx(1.01 * std::sqrt(2.0)));
  const double rows = neighbourhoodRadius(lattice(0.31, 0.75));
  CHECK(rows >= std::hypot(0.31, 0.75));
  CHECK(rows < 1.0);
  CHECK(neighbourhoodRadius(lattice(1.46, 1.46)) == doctest::Approx(1.01 * 1.46 * std::sqrt(2.0)));
  // Corridors: two lattice rooms joined by a one-sample-wide line, most of
  // whose samples have their 8th nearest two steps away; the rooms' inner
  // samples still set the radius.
  std::vector<glm::dvec2> corridors = lattice(1.0, 1.0);
  for (int k = 1; k <= 400; ++k) corridors.emplace_back(19.0 + k, 5.0);
  CHECK(neighbourhoodRadius(corridors) == doctest::Approx(1.01 * std::sqrt(2.0)));
}

TEST_CASE("decimation serves samples outside the mesh as eval does: the nearest triangle that sees them") {
  // Two 4 x 3 m rooms joined by a 1 m doorway, a grid of samples 0.5 m
  // apart inside, each moved by a few millimetres so that no sample lies on
  // an edge between two triangles (either may serve it, and eval and the
  // decimator break that tie differently); a reference reconstructs a
  // sample it cannot see badly.
  const WalkableRegion region(
      {{{{0, 0}, {4, 0}, {4, 1}, {4.5, 1}, {4.5, 0}, {8.5, 0}, {8.5, 3}, {4.5, 3}, {4.5, 2}, {4, 2}, {4, 3}, {0, 3}}, {}}},
      "two rooms");
  std::vector<glm::dvec2> positions;
  for (double x = 0.25; x < 8.5; x += 0.5) {
    for (double y = 0.25; y < 3.0; y += 0.5) {
      const glm::dvec2 jitter(0.003 * std::sin(37.0 * x + 11.0 * y), 0.003 * std::cos(17.0 * x - 29.0 * y));
      if (region.contains({x, y})) positions.push_back(glm::dvec2(x, y) + jitter);
    }
  }
  const FormulaErrors::Formula formula = distanceAndSightErrors(positions, region);
  FormulaErrors errors(formula);
  DecimationOptions options;
  options.maxError = 0.0;
  options.targetSamples = 8;
  EdgeCollapseDecimator decimator(ViewMesh::delaunay(positions, {}, "two rooms", &region), DecimationErrors{nullptr, &errors},
                                  options);
  int blindNearest = 0;  // outside samples whose nearest triangle is behind a wall: the case under test
  while (decimator.step()) {
    const ViewMesh mesh = decimator.mesh();
    CHECK(decimator.servedSampleMeanError() == doctest::Approx(meanError(mesh, formula)).epsilon(1e-12));
    for (int i = 0; i < int(positions.size()); ++i) {
      if (std::binary_search(mesh.vertices().begin(), mesh.vertices().end(), i)) continue;
      int nearest = 0;
      for (int t = 1; t < mesh.triangleCount(); ++t) {
        if (mesh.distanceToTriangle(t, positions[size_t(i)]) < mesh.distanceToTriangle(nearest, positions[size_t(i)])) nearest = t;
      }
      blindNearest += mesh.servingRank(nearest, positions[size_t(i)]).blind;
    }
  }
  CHECK(decimator.vertexCount() == 8);
  CHECK(blindNearest > 0);
}

TEST_CASE(
    "where the boundary may shrink, a reference leaves a straight stretch of it only once no other collapse is "
    "valid, a ring is cut open only once none of those is, and the covered area only shrinks") {
  // A 10 x 6 m room around a 6 x 2 m block, sampled on a 1 m lattice (as a
  // capture samples a region): a corridor two samples wide all round,
  // every sample on the boundary, every side a straight row. No collapse
  // cuts a ring, so once its corners are cut off the collapses left are
  // those that take a reference off a straight side, and once the ring is
  // as thin as it can be, only a reference removed with its triangles
  // (cutting the ring open) lets it go on to the target.
  RegionPolygon ring;
  ring.outer = {{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  ring.holes = {{{2, 2}, {2, 4}, {8, 4}, {8, 2}}};
  const WalkableRegion region({ring}, "ring");
  std::vector<glm::dvec2> positions;
  for (double x = 0.5; x < 10.0; x += 1.0) {
    for (double y = 0.5; y < 6.0; y += 1.0) {
      if (region.contains({x, y})) positions.push_back({x, y});
    }
  }
  REQUIRE(positions.size() == 48);
  auto sampleAt = [&](double x, double y) {
    return int(std::find(positions.begin(), positions.end(), glm::dvec2(x, y)) - positions.begin());
  };
  const FormulaErrors::Formula formula = distanceAndSightErrors(positions, region);
  FormulaErrors errors(formula);
  DecimationOptions options;
  options.maxError = 0.0;
  options.targetSamples = 8;
  const ViewMesh dense = ViewMesh::delaunay(positions, {}, "ring", &region);
  EdgeCollapseDecimator decimator(dense, DecimationErrors{nullptr, &errors}, options);

  // (2.5, 0.5) lies on the south side between (1.5, 0.5) and (3.5, 0.5);
  // while other collapses are valid (a corner's) it stays.
  CHECK_FALSE(decimator.isValidCollapse(sampleAt(2.5, 0.5), sampleAt(3.5, 0.5), sampleAt(3.5, 0.5)));
  CHECK(decimator.isValidCollapse(sampleAt(0.5, 0.5), sampleAt(1.5, 0.5), sampleAt(1.5, 0.5)));

  auto area = [&](const ViewMesh& mesh) {
    double sum = 0.0;
    for (const Triangle& t : mesh.triangles()) {
      const glm::dvec2 a = positions[size_t(t[0])], b = positions[size_t(t[1])], c = positions[size_t(t[2])];
      sum += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    }
    return sum;
  };
  // No collapse onto an endpoint or a free sample is valid in this mesh,
  // as a decimator that has just been made from it sees it.
  auto stuck = [&](const ViewMesh& mesh) {
    FormulaErrors freshErrors(formula);
    EdgeCollapseDecimator fresh(mesh, DecimationErrors{nullptr, &freshErrors}, options);
    for (const Triangle& t : mesh.triangles()) {
      for (int e = 0; e < 3; ++e) {
        for (int placement = 0; placement < int(positions.size()); ++placement) {
          if (fresh.isValidCollapse(t[size_t(e)], t[size_t((e + 1) % 3)], placement)) return false;
        }
      }
    }
    return true;
  };
  // One edge-connected piece, every vertex on the boundary once at most.
  auto onePieceNoPinch = [&](const ViewMesh& mesh) {
    std::map<std::pair<int, int>, int> uses;
    for (const Triangle& t : mesh.triangles()) {
      for (int e = 0; e < 3; ++e) ++uses[std::minmax(t[size_t(e)], t[size_t((e + 1) % 3)])];
    }
    std::map<int, int> boundaryEdges;
    for (const auto& [edge, count] : uses) {
      if (count == 1) ++boundaryEdges[edge.first], ++boundaryEdges[edge.second];
    }
    const bool noPinch =
        std::all_of(boundaryEdges.begin(), boundaryEdges.end(), [](const auto& vertex) { return vertex.second <= 2; });
    std::vector<char> reached(mesh.triangles().size(), 0);
    std::vector<size_t> stack = {0};
    reached[0] = 1;
    while (!stack.empty()) {
      const Triangle t = mesh.triangles()[stack.back()];
      stack.pop_back();
      for (size_t o = 0; o < reached.size(); ++o) {
        int shared = 0;
        for (int v : mesh.triangles()[o]) shared += int(std::find(t.begin(), t.end(), v) != t.end());
        if (!reached[o] && shared == 2) reached[o] = 1, stack.push_back(o);
      }
    }
    return noPinch && std::all_of(reached.begin(), reached.end(), [](char r) { return r == 1; });
  };
  ViewMesh before = dense;
  uint64_t lastResorts = 0, removals = 0;
  while (decimator.step()) {
    const ViewMesh after = decimator.mesh();
    const Collapse& made = decimator.log().back();
    if (decimator.statistics().straightStretchSearches > lastResorts) {
      lastResorts = decimator.statistics().straightStretchSearches;
      CHECK(stuck(before));
    }
    if (made.kind == PlacementKind::Removal) {
      // Only where no collapse is valid, the straight-stretch ones
      // included: the first where they ran out, at 15 references.
      if (removals == 0) CHECK(before.vertices().size() == 15);
      ++removals;
      CHECK(decimator.statistics().removals == removals);
      CHECK(stuck(before));
      CHECK(made.added.empty());
      CHECK(made.second == made.placement);
    }
    CHECK(onePieceNoPinch(after));
    // The rule depends on the mesh alone: a decimator made from the mesh
    // before makes the same collapse (after a last resort, the next
    // collapse is an ordinary one again wherever one is valid).
    FormulaErrors freshErrors(formula);
    EdgeCollapseDecimator fresh(before, DecimationErrors{nullptr, &freshErrors}, options);
    const std::optional<Collapse> next = fresh.peekNextCollapse();
    REQUIRE(next);
    CHECK(next->placement == made.placement);
    CHECK(next->removed == made.removed);
    CHECK(next->cost == made.cost);
    // Every collapse covers a part of what the mesh covered before, inside the region.
    CHECK(area(after) <= area(before) + 1e-12);
    for (const Triangle& t : after.triangles()) {
      const glm::dvec2 a = positions[size_t(t[0])], b = positions[size_t(t[1])], c = positions[size_t(t[2])];
      CHECK(region.containsTriangle(a, b, c));
      for (const glm::dvec2& corner : {a, b, c}) {
        const glm::dvec2 point = corner + 1e-3 * ((a + b + c) / 3.0 - corner);
        CHECK(before.contains(before.locate(point), point));
      }
    }
    before = after;
  }
  // Without the last resorts the ring stops at 26 references; without
  // removals at 15.
  CHECK(lastResorts > 0);
  CHECK(removals > 0);
  CHECK(decimator.stopReason() == StopReason::TargetReached);
  CHECK(decimator.vertexCount() == 8);

  // Under a threshold that the last resorts' collapses cross (6.4 here:
  // 28 references before any, 16 after ten) the decimator stops where one
  // made afresh from its final mesh stops too: a last resort's refusals
  // must not stand for ordinary ones and stop a later search early.
  options.targetSamples = 0;
  options.maxError = 6.4;
  EdgeCollapseDecimator thresholded(dense, DecimationErrors{nullptr, &errors}, options);
  while (thresholded.step()) {
  }
  CHECK(thresholded.stopReason() == StopReason::MaxError);
  CHECK(thresholded.statistics().straightStretchSearches > 0);
  FormulaErrors finalErrors(formula);
  EdgeCollapseDecimator afresh(thresholded.mesh(), DecimationErrors{nullptr, &finalErrors}, options);
  CHECK_FALSE(afresh.peekNextCollapse());
}

TEST_CASE("a reference leaves with its triangles only where the mesh stays one piece and pinches nowhere") {
  FormulaErrors errors([](const Triangle&, int) { return 1.0; });
  DecimationOptions options;
  options.maxError = 0.0;
  // A corridor one triangle wide: bottom row p0..p3, top row q0..q3.
  std::vector<glm::dvec2> strip;
  for (int i = 0; i < 4; ++i) strip.emplace_back(i, 0.0);
  for (int i = 0; i < 4; ++i) strip.emplace_back(i, 1.0);
  std::vector<Triangle> zigzag;
  for (int i = 0; i < 3; ++i) {
    zigzag.push_back({i, i + 1, 4 + i});
    zigzag.push_back({i + 1, 5 + i, 4 + i});
  }
  const EdgeCollapseDecimator corridor(ViewMesh(strip, zigzag), DecimationErrors{nullptr, &errors}, options);
  CHECK(corridor.isValidRemoval(0, 1));        // p0 from the corridor's end
  CHECK_FALSE(corridor.isValidRemoval(5, 4));  // q1 would cut the corridor in two
  CHECK_FALSE(corridor.isValidRemoval(4, 5));  // q0 would leave p0 without a triangle
  CHECK_FALSE(corridor.isValidRemoval(0, 2));  // not an edge
  // w = (0, 0) on the bottom edge, its fan L-A-v-B-R; v = (0, 1) on the
  // edge of a hole, which an arch of triangles from A over to B closes.
  // Without v, w would hold two fans (a pinch), though the mesh stays one
  // piece round the arch.
  const std::vector<glm::dvec2> arch = {{0, 0},  {-1, 0}, {1, 0},  {-1, 1}, {0, 1}, {1, 1},
                                        {-2, 1}, {-1, 2}, {-2, 3}, {1, 2},  {2, 3}, {2, 1}};
  enum { W, L, R, A, V, B, A2, C, P, D, Q, B2 };
  const std::vector<Triangle> around = {{L, W, A},  {W, V, A},  {W, B, V}, {W, R, B}, {L, A, A2}, {R, B2, B},
                                        {A2, A, C}, {A2, C, P}, {P, C, D}, {P, D, Q}, {Q, D, B},  {Q, B, B2}};
  const EdgeCollapseDecimator pinched(ViewMesh(arch, around), DecimationErrors{nullptr, &errors}, options);
  CHECK_FALSE(pinched.isValidRemoval(V, A));
  CHECK_FALSE(pinched.isValidRemoval(V, B));
  CHECK(pinched.isValidRemoval(C, A));         // the arch cut open next to A
  CHECK_FALSE(pinched.isValidRemoval(C, A2));  // not along the boundary
  // With the fixed boundary (the paper's rule) nothing leaves.
  options.fixedBoundary = true;
  const EdgeCollapseDecimator fixed(ViewMesh(strip, zigzag), DecimationErrors{nullptr, &errors}, options);
  CHECK_FALSE(fixed.isValidRemoval(0, 1));
}

namespace {

// Two 4 x 3 m rooms joined by a doorway, sampled every 0.3 m with a little
// jitter (no sample on an edge), and errors that grow with the distance to
// the references and jump behind a wall: late collapses serve dozens of
// samples each, so pricing and screening have work to cut.
struct TwoRooms {
  WalkableRegion region{
      {{{{0, 0}, {4, 0}, {4, 1}, {4.5, 1}, {4.5, 0}, {8.5, 0}, {8.5, 3}, {4.5, 3}, {4.5, 2}, {4, 2}, {4, 3}, {0, 3}},
        {}}},
      "two rooms"};
  std::vector<glm::dvec2> positions;
  FormulaErrors::Formula formula;

  TwoRooms() {
    for (double x = 0.15; x < 8.5; x += 0.3) {
      for (double y = 0.15; y < 3.0; y += 0.3) {
        const glm::dvec2 jitter(0.003 * std::sin(37.0 * x + 11.0 * y), 0.003 * std::cos(17.0 * x - 29.0 * y));
        if (region.contains({x, y})) positions.push_back(glm::dvec2(x, y) + jitter);
      }
    }
    formula = distanceAndSightErrors(positions, region);
  }
  ViewMesh dense() const { return ViewMesh::delaunay(positions, {}, "two rooms", &region); }
};

// Twelve references of the two rooms crowded into the left one: most must
// move, some across the doorway (exchanges).
ViewMesh crowdedLeftRoom(const TwoRooms& rooms) {
  std::vector<int> references;
  for (int i = 0; i < int(rooms.positions.size()) && references.size() < 12; ++i) {
    if (rooms.positions[size_t(i)].x < 1.0 && std::fmod(double(i), 5.0) == 0.0) references.push_back(i);
  }
  const int corners[] = {0, 9};  // (0.15, 0.15) and (0.15, 2.85): keep the left wall covered
  references.insert(references.end(), std::begin(corners), std::end(corners));
  std::sort(references.begin(), references.end());
  references.erase(std::unique(references.begin(), references.end()), references.end());
  return ViewMesh::delaunay(rooms.positions, references, "two rooms", &rooms.region);
}

// The two rooms refined from crowdedLeftRoom, screened or priced (0: not),
// and how many errors that computed.
std::pair<RefinementResult, int> refineCrowdedRooms(const TwoRooms& rooms, double screenedShare, int priced,
                                                    int repricing = RefinementOptions{}.repricing) {
  FormulaErrors errors(rooms.formula);
  RefinementOptions options;
  options.region = &rooms.region;
  options.screenedShare = screenedShare;
  options.pricedSamples = priced;
  options.repricing = repricing;
  const RefinementResult result = refineSelection(rooms.positions, crowdedLeftRoom(rooms).triangles(), errors, options);
  return {result, errors.computed};
}

// Every move lowered the exact objective, and the objective reported is
// the exact one of the final mesh.
void checkExactObjectiveFalls(const TwoRooms& rooms, const RefinementResult& result) {
  double previous = result.objectiveBefore;
  for (const Collapse& move : result.moves) {
    CHECK(move.cost < previous);
    previous = move.cost;
  }
  const ViewMesh final(rooms.positions, result.triangles, sharedRegion(&rooms.region));
  CHECK(result.objectiveAfter == doctest::Approx(meanError(final, rooms.formula)).epsilon(1e-12));
}

// The same moves (reference, placement, objective after each) and the
// same final objective.
void checkSameMoves(const RefinementResult& result, const RefinementResult& expected) {
  REQUIRE(result.moves.size() == expected.moves.size());
  for (size_t i = 0; i < expected.moves.size(); ++i) {
    CHECK(result.moves[i].first == expected.moves[i].first);
    CHECK(result.moves[i].placement == expected.moves[i].placement);
    CHECK(result.moves[i].cost == expected.moves[i].cost);
  }
  CHECK(result.objectiveAfter == expected.objectiveAfter);
}

}  // namespace

TEST_CASE(
    "pricing collapses on a subset of their served samples: fewer errors, exact errors kept, the same when "
    "the subset is all") {
  const TwoRooms rooms;
  REQUIRE(rooms.positions.size() > 250);
  auto decimate = [&](int priced, bool lazy) {
    FormulaErrors errors(rooms.formula);
    DecimationOptions options;
    options.maxError = 0.0;
    options.targetSamples = 12;
    options.pricedSamples = priced;
    options.lazyRecosting = lazy;
    EdgeCollapseDecimator decimator(rooms.dense(), DecimationErrors{nullptr, &errors}, options);
    while (decimator.step()) {
      // The errors the samples are served with stay exact, priced or not.
      REQUIRE(decimator.servedSampleMeanError() ==
              doctest::Approx(meanError(decimator.mesh(), rooms.formula)).epsilon(1e-12));
    }
    CHECK(decimator.vertexCount() == 12);
    return std::tuple(decimator.log(), errors.computed, decimator.servedSampleMeanError());
  };
  const auto [exactLog, exactErrors, exactMean] = decimate(0, false);
  // A subset larger than any collapse serves prices exactly.
  const auto [allLog, allErrors, allMean] = decimate(1000, false);
  REQUIRE(allLog.size() == exactLog.size());
  for (size_t i = 0; i < exactLog.size(); ++i) {
    CHECK(allLog[i].placement == exactLog[i].placement);
    CHECK(allLog[i].cost == exactLog[i].cost);
  }
  // 8 samples per collapse: late collapses serve dozens, so fewer errors;
  // the selection is not far from the exact one.
  const auto [pricedLog, pricedErrors, pricedMean] = decimate(8, false);
  CHECK(pricedErrors < exactErrors * 3 / 4);
  CHECK(pricedMean < 1.2 * exactMean);
  // Lazy re-costing: fewer errors (each collapse is re-costed before it is made).
  const auto [lazyLog, lazyErrors, lazyMean] = decimate(0, true);
  CHECK(lazyErrors < exactErrors);
  CHECK(lazyMean < 1.2 * exactMean);
  MESSAGE("errors computed: exact ", exactErrors, ", priced 8 ", pricedErrors, ", lazy ", lazyErrors, "; mean error ",
          exactMean, " / ", pricedMean, " / ", lazyMean);
}

TEST_CASE("a lazily re-costed decimator makes each collapse at the cost a fresh evaluation gives it") {
  const TwoRooms rooms;
  FormulaErrors errors(rooms.formula);
  DecimationOptions options;
  options.maxError = 0.0;
  options.targetSamples = 40;
  options.lazyRecosting = true;
  EdgeCollapseDecimator decimator(rooms.dense(), DecimationErrors{nullptr, &errors}, options);
  while (true) {
    const std::optional<Collapse> next = decimator.peekNextCollapse();
    if (!next || decimator.vertexCount() <= 40) break;
    const std::optional<Collapse> fresh = decimator.evaluateCollapse(next->first, next->second, next->placement);
    REQUIRE(fresh);
    CHECK(fresh->cost == next->cost);
    REQUIRE(decimator.step());
    CHECK(decimator.log().back().placement == next->placement);
  }
  CHECK(decimator.vertexCount() == 40);
}

TEST_CASE("screened refinement: fewer errors, only moves that lower the exact objective") {
  const TwoRooms rooms;
  const auto [exact, exactErrors] = refineCrowdedRooms(rooms, 0.0, 0);
  const auto [screened, screenedErrors] = refineCrowdedRooms(rooms, 0.25, 0);
  REQUIRE(screened.moves.size() >= 3);
  CHECK(screened.exchanges >= 1);
  CHECK(screenedErrors < exactErrors * 3 / 4);
  checkExactObjectiveFalls(rooms, screened);
  CHECK(screened.objectiveAfter < 0.8 * screened.objectiveBefore);
  CHECK(screened.objectiveAfter < 1.1 * exact.objectiveAfter);
  MESSAGE("refinement: exact ", exact.objectiveAfter, " with ", exactErrors, " errors; screened ",
          screened.objectiveAfter, " with ", screenedErrors);
}

TEST_CASE("priced refinement: fewer errors, only moves that lower the exact objective, exact when the subset is all") {
  const TwoRooms rooms;
  const auto [exact, exactErrors] = refineCrowdedRooms(rooms, 0.0, 0);
  // A subset larger than any candidate changes: every candidate is exact,
  // and so is every move.
  const auto [all, allErrors] = refineCrowdedRooms(rooms, 0.0, 100000);
  checkSameMoves(all, exact);
  // 8 samples per candidate: most candidates change dozens; those whose
  // estimate comes within two standard errors of the selection are scored
  // exactly.
  const auto [priced, pricedErrors] = refineCrowdedRooms(rooms, 0.0, 8);
  REQUIRE(priced.moves.size() >= 3);
  CHECK(priced.exchanges >= 1);
  CHECK(pricedErrors < exactErrors * 3 / 4);
  checkExactObjectiveFalls(rooms, priced);
  CHECK(priced.objectiveAfter < 1.02 * exact.objectiveAfter);
  MESSAGE("refinement: exact ", exact.objectiveAfter, " with ", exactErrors, " errors; priced on 8 ",
          priced.objectiveAfter, " with ", pricedErrors);
}

TEST_CASE("the exchange search prices its single removals and insertions: the exact search's exchanges, fewer errors") {
  // Local moves reach no sample (1 cm), so every move is an exchange and
  // every error computed after the start is the exchange search's.
  const TwoRooms rooms;
  auto exchangeOnly = [&](int priced, int repricing) {
    FormulaErrors errors(rooms.formula);
    RefinementOptions options;
    options.radius = 0.01;
    options.region = &rooms.region;
    options.pricedSamples = priced;
    options.repricing = repricing;
    const RefinementResult result =
        refineSelection(rooms.positions, crowdedLeftRoom(rooms).triangles(), errors, options);
    return std::pair(result, errors.computed);
  };
  const auto [exact, exactErrors] = exchangeOnly(0, 1);
  const auto [priced, pricedErrors] = exchangeOnly(8, 1);
  REQUIRE(exact.exchanges >= 2);
  checkSameMoves(priced, exact);
  CHECK(pricedErrors < exactErrors * 9 / 10);
  checkExactObjectiveFalls(rooms, priced);
  // The singles that may rank among the lowest priced again on 32 first.
  const auto [repriced, repricedErrors] = exchangeOnly(8, 4);
  checkSameMoves(repriced, exact);
  CHECK(repricedErrors < pricedErrors);
  MESSAGE("exchange search: ", exact.exchanges, " exchanges; exact ", exactErrors, " errors, priced on 8 ",
          pricedErrors, ", and again on 32 ", repricedErrors);
}

TEST_CASE(
    "local moves that may beat the selection are priced again on more samples first: the same moves, fewer errors") {
  const TwoRooms rooms;
  const auto [once, onceErrors] = refineCrowdedRooms(rooms, 0.0, 8, 1);
  const auto [again, againErrors] = refineCrowdedRooms(rooms, 0.0, 8, 4);
  checkSameMoves(again, once);
  CHECK(againErrors < onceErrors);
  MESSAGE("priced on 8: ", onceErrors, " errors; again on 32 first: ", againErrors);
}

TEST_CASE("Ctrl-C stops the exchange search between chunks of its errors, not after the whole search") {
  const TwoRooms rooms;
  constexpr int kStopAfter = 2000;  // errors: past the start (about 500), inside the first exchange search
  int seen = 0;
  FormulaErrors stopping([&](const Triangle& t, int destination) {
    if (++seen == kStopAfter) requestInterrupt();
    return rooms.formula(t, destination);
  });
  RefinementOptions options;
  options.radius = 0.01;  // no local moves: only exchange searches
  options.region = &rooms.region;
  options.pricedSamples = 0;
  ProgressReporter progress("refine", 0, true);
  CHECK_THROWS_AS(refineSelection(rooms.positions, crowdedLeftRoom(rooms).triangles(), stopping, options, &progress),
                  Interrupted);
  clearInterrupt();
  // At most the rest of the chunk (64 errors) after the stop was asked.
  CHECK(stopping.computed >= kStopAfter);
  CHECK(stopping.computed < kStopAfter + 64);
}

TEST_CASE("the refinement's progress line gives the time left of the pass it is in, not of the refinement") {
  // A pass's count is all a reporter knows; the passes and exchange
  // searches after it are not, so the time left must say it is the pass's.
  ProgressReporter bare("refine: move references", 0, true);
  CHECK(bare.line(false).find("left") == std::string::npos);  // no total: no time left
  bare.advance(3);
  bare.setTotal(8, "pass 2");
  CHECK(bare.line(false).find("3/8") != std::string::npos);
  CHECK(bare.line(false).find(" of pass 2") != std::string::npos);
  CHECK(bare.line(true).find("left") == std::string::npos);
  bare.setTotal(8);
  CHECK(bare.line(false).find("left") != std::string::npos);
  CHECK(bare.line(false).find(" of ") == std::string::npos);

  const TwoRooms rooms;
  ProgressReporter progress("refine: move references", 0, true);
  std::set<std::string> scopes;  // each " of pass N" the line showed
  FormulaErrors errors([&](const Triangle& t, int destination) {
    const std::string line = progress.line(false);
    const size_t at = line.find(" of pass ");
    if (at != std::string::npos) scopes.insert(line.substr(at, line.find("  ", at) - at));
    return rooms.formula(t, destination);
  });
  RefinementOptions options;
  options.radius = 1.5;
  options.region = &rooms.region;
  options.maxExchanges = 0;
  const RefinementResult result =
      refineSelection(rooms.positions, crowdedLeftRoom(rooms).triangles(), errors, options, &progress);
  REQUIRE(result.passes >= 2);
  CHECK(scopes.count(" of pass 1") == 1);
  CHECK(scopes.count(" of pass 2") == 1);
  CHECK(scopes.size() <= size_t(result.passes));
}

namespace {

// The small captured data set the tests below decimate: 5 x 3 samples of
// 64 x 32 pixels, and errors at that width.
struct SmallCapture {
  testing::TemporaryDirectory directory;
  Dataset dataset = write(directory);

  static TriangleErrorSettings errorSettings() {
    TriangleErrorSettings settings;
    settings.width = 64;
    return settings;
  }

private:
  static Dataset write(const testing::TemporaryDirectory& directory) {
    testing::writeAnalyticDataset(directory / "data", 5, 3, 64, 1);
    return Dataset::open(directory / "data");
  }
};

// A small captured data set decimated to 5 samples and refined, as the
// selection runs it, with the thread count given.
struct DecimatedAndRefined {
  std::vector<Collapse> log;  // the collapses, then the moves
  RefinementResult refinement;
  uint64_t layersWarped = 0;
  uint64_t layersWarpedAgain = 0;  // after the cache dropped them
};

DecimatedAndRefined decimateAndRefine(const Dataset& dataset, const TriangleErrorSettings& settings, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  const ViewMesh initial = ViewMesh::delaunay(positions, {}, "test");
  DatasetTriangleErrors errors(dataset, settings, LoadedViews::Samples, true);
  DecimationOptions options;  // the default cost (served samples), with the paper's fixed boundary so that
  options.maxError = 0.0;     // the refinement has references on the boundary to move
  options.targetSamples = 5;
  options.fixedBoundary = true;
  options.pricedSamples = 2;  // so that pricing subsets have work here, in the collapses and the refinement
  EdgeCollapseDecimator decimator(initial, DecimationErrors{&errors, &errors}, options);
  decimator.run();
  DecimatedAndRefined result;
  result.refinement = refineSelection(positions, decimator.mesh().triangles(), errors, {10.0, 8, {}, nullptr, {}, 0.0, 2});
  result.log = decimator.log();
  result.log.insert(result.log.end(), result.refinement.moves.begin(), result.refinement.moves.end());
  result.layersWarped = errors.layerCache().misses();
  result.layersWarpedAgain = errors.layerCache().missesAfterEviction();
  return result;
}

void checkSameSelection(const DecimatedAndRefined& a, const DecimatedAndRefined& b) {
  REQUIRE(a.log.size() == b.log.size());
  for (size_t i = 0; i < a.log.size(); ++i) {
    CHECK(a.log[i].kind == b.log[i].kind);
    CHECK(a.log[i].placement == b.log[i].placement);
    CHECK(a.log[i].cost == b.log[i].cost);
    CHECK(a.log[i].added == b.log[i].added);
  }
  CHECK(a.refinement.triangles == b.refinement.triangles);
}

}  // namespace

TEST_CASE(
    "a captured data set: decimation then refinement, the same with 1 and 2 threads (grid and simplified source "
    "meshes), and through selection.json") {
  const SmallCapture capture;
  const Dataset& dataset = capture.dataset;
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  const ViewMesh initial = ViewMesh::delaunay(positions, {}, "test");
  TriangleErrorSettings settings = SmallCapture::errorSettings();
  std::vector<Collapse> one;  // the grid's, for the selection file below
  RefinementResult refinedOne;
  for (const SourceMesh mesh : {SourceMesh::Simplified, SourceMesh::Grid}) {
    INFO(sourceMeshName(mesh) << " source mesh");
    settings.synthesis.warp.mesh = mesh;
    const DecimatedAndRefined first = decimateAndRefine(dataset, settings, 1);
    const DecimatedAndRefined second = decimateAndRefine(dataset, settings, 2);
    one = first.log;
    refinedOne = first.refinement;
    REQUIRE(!refinedOne.moves.empty());
    REQUIRE(one.size() == 10 + refinedOne.moves.size());  // 15 samples collapsed to 5, then the moves
    checkSameSelection(first, second);
    CHECK(refinedOne.objectiveAfter <= refinedOne.objectiveBefore);
  }

  Selection selection;
  selection.method = "edge_collapse";
  selection.samples = ViewMesh(positions, refinedOne.triangles).vertices();
  selection.triangles = refinedOne.triangles;
  selection.initialTriangles = initial.triangles();
  selection.collapses = one;
  const std::filesystem::path file = capture.directory / "selection.json";
  writeSelection(file, selection, dataset);
  const Selection loaded = readSelection(file, dataset);
  REQUIRE(loaded.collapses.size() == one.size());
  for (size_t i = 0; i < one.size(); ++i) {
    CHECK(loaded.collapses[i].kind == one[i].kind);
    CHECK(loaded.collapses[i].first == one[i].first);
    CHECK(loaded.collapses[i].second == one[i].second);
    CHECK(loaded.collapses[i].placement == one[i].placement);
  }
  CHECK(loaded.triangles == refinedOne.triangles);
  CHECK(samplesAfter(initial.vertexCount(), loaded.collapses, loaded.collapses.size()) == 5);
}

TEST_CASE("the selection's errors on a lattice: the whole warp's blend at its pixels, and the same selection with 1 and 2 threads") {
  const SmallCapture capture;
  const Dataset& dataset = capture.dataset;
  TriangleErrorSettings settings = SmallCapture::errorSettings();
  settings.synthesis = withSelectionDefaults(settings.synthesis);
  TriangleErrorSettings lattice = settings;
  lattice.stride = 2;
  DatasetTriangleErrors whole(dataset, settings, LoadedViews::Samples, true);
  DatasetTriangleErrors sparse(dataset, lattice, LoadedViews::Samples, true);
  const std::vector<SampleReconstruction> requests = {{{0, 1, 3}, 4}, {{2, 7, 12}, 6}, {{0, 5, 14}, 9}, {{1, 4, 10}, 8}};
  std::vector<double> wholeErrors(requests.size()), sparseErrors(requests.size());
  whole.computeReconstructionErrors(requests, wholeErrors);
  sparse.computeReconstructionErrors(requests, sparseErrors);
  for (size_t k = 0; k < requests.size(); ++k) {
    // The expected error, from the whole panorama's warps kept as the cache
    // keeps them, blended and compared at the lattice's pixels alone.
    const int destination = requests[k].destination;
    const glm::vec3 position = dataset.sample(destination).position;
    const DestinationCamera camera = DestinationCamera::panorama(position, 64, 32);
    DecodedLayerRow layers[3];
    glm::vec3 sourcePositions[3];
    for (int i = 0; i < 3; ++i) {
      const WarpSource& source = whole.source(requests[k].references[size_t(i)]);
      const CompactLayer layer(warpToCamera(source, camera, settings.synthesis.warp.method, LayerReliability::Omitted));
      layer.decodeRow(0, layer.pixelCount(), layers[i]);
      sourcePositions[i] = source.position();
    }
    const DecodedLayerRow* pointers[3] = {&layers[0], &layers[1], &layers[2]};
    const std::vector<float> weights = blendWeights(position, sourcePositions, settings.synthesis.blend);
    const ColorImage& truth = whole.sampleDisplay(destination);
    ErrorAccumulator expected(64, 32, settings.error, 2);
    for (int y = 0; y < 32; y += 2) {
      for (int x = 0; x < 64; x += 2) {
        const size_t i = size_t(y) * 64 + size_t(x);
        const BlendedPixel pixel = blendPixelOf<DecodedLayerRow>(pointers, weights, i, settings.synthesis.blend);
        expected.add(y, displayColorFast(pixel.color), pixel.hole, truth.pixels[i]);
      }
    }
    INFO("request " << k << ": every pixel " << wholeErrors[k] << ", the lattice " << sparseErrors[k]);
    CHECK(sparseErrors[k] == expected.result().total);
    CHECK(sparseErrors[k] != wholeErrors[k]);
    CHECK(std::abs(sparseErrors[k] - wholeErrors[k]) < 0.2 * wholeErrors[k]);
  }

  const DecimatedAndRefined first = decimateAndRefine(dataset, lattice, 1);
  const DecimatedAndRefined second = decimateAndRefine(dataset, lattice, 2);
  REQUIRE(first.log.size() >= 10);
  checkSameSelection(first, second);
}

TEST_CASE("the viewer's decimator takes decimate's steps: the samples weighed by their area, the region serving them") {
  const SmallCapture capture;
  const Dataset& dataset = capture.dataset;
  TriangleErrorSettings errorSettings = SmallCapture::errorSettings();
  errorSettings.synthesis = withSelectionDefaults(errorSettings.synthesis);
  DatasetTriangleErrors errors(dataset, errorSettings, LoadedViews::Samples, true);
  SelectionSettings settings;
  settings.decimation.maxError = 0.0;
  settings.decimation.targetSamples = 4;
  settings.refinement.radius = 0.0;
  const SelectionRun decimate = selectReferences(dataset, errors, settings, true);
  REQUIRE(decimate.collapses == 11);

  const std::vector<Triangle> dense = datasetMesh(dataset, {}, "test").triangles();
  CachingReconstructionErrors sampleErrors(errors);
  const std::unique_ptr<EdgeCollapseDecimator> viewer =
      datasetDecimator(dataset, dense, DecimationErrors{&errors, &sampleErrors}, settings.decimation);
  viewer->run();
  const std::vector<Collapse>& steps = viewer->log();
  REQUIRE(steps.size() == decimate.selection.collapses.size());
  for (size_t i = 0; i < steps.size(); ++i) {
    CAPTURE(i);
    CHECK(steps[i].first == decimate.selection.collapses[i].first);
    CHECK(steps[i].placement == decimate.selection.collapses[i].placement);
    CHECK(steps[i].cost == decimate.selection.collapses[i].cost);
  }

  // What the viewer did before: every sample weighing alike, no region.
  // Its costs are not decimate's (the grid's edge samples stand for half
  // the area of its inner ones), so the comparison above can fail.
  EdgeCollapseDecimator unweighted(ViewMesh(samplePositions(dataset), dense), DecimationErrors{&errors, &sampleErrors},
                                   settings.decimation);
  unweighted.run();
  bool differs = unweighted.log().size() != steps.size();
  for (size_t i = 0; !differs && i < steps.size(); ++i) differs = unweighted.log()[i].cost != steps[i].cost;
  CHECK(differs);
}

TEST_CASE("the warped-layer cache's budget changes how many layers are warped, never the selection") {
  const SmallCapture capture;
  const Dataset& dataset = capture.dataset;
  TriangleErrorSettings settings = SmallCapture::errorSettings();
  // One thread, so that no two threads warp the same layer at once and the
  // counts are exact.
  const DecimatedAndRefined automatic = decimateAndRefine(dataset, settings, 1);
  settings.layerCacheBytes = 1;  // one layer kept: nearly every request warps again
  const DecimatedAndRefined starved = decimateAndRefine(dataset, settings, 1);
  checkSameSelection(automatic, starved);
  CHECK(starved.layersWarped > 2 * automatic.layersWarped);
  // Every layer is warped once; only the starved cache warps any again.
  CHECK(automatic.layersWarpedAgain == 0);
  CHECK(starved.layersWarped - starved.layersWarpedAgain == automatic.layersWarped);
  CHECK(automaticLayerCacheBytes() >= size_t(1) << 30);
}

TEST_CASE("a layer cache short of memory lowers its budget by the shortfall, never below its floor, never up again") {
  // Layers of 8x4 pixels (4 planes of halves, no reliability: 256 bytes).
  const auto layerOf = [] {
    WarpLayer layer{ColorImage(8, 4), ScalarImage(8, 4, 1.0f), std::vector<uint8_t>(32, 1), 0, 0, {}, {}};
    return layer;
  };
  const size_t layerBytes = CompactLayer(layerOf()).bytes();
  REQUIRE(layerBytes == 256);
  WarpLayerCache cache(1000 * layerBytes);
  size_t available = 1 << 30;
  const size_t reserve = 100 * layerBytes, floor = 40 * layerBytes;
  cache.watchMemory([&]() -> std::optional<size_t> { return available; }, reserve, floor);
  int next = 0;
  const auto missMany = [&](uint64_t misses) {
    for (uint64_t i = 0; i < misses; ++i, ++next) cache.get(next, 0, layerOf);
  };
  missMany(2 * WarpLayerCache::kMissesBetweenChecks);
  CHECK(cache.budgetCuts() == 0);
  CHECK(cache.budgetBytes() == 1000 * layerBytes);
  CHECK(cache.bytes() == 128 * layerBytes);
  // Another process takes memory: 30 layers' worth short of the reserve.
  // Nothing changes before the next check, then the budget drops by the
  // shortfall below what the cache holds.
  available = reserve - 30 * layerBytes;
  missMany(WarpLayerCache::kMissesBetweenChecks - 1);
  CHECK(cache.budgetCuts() == 0);
  missMany(1);
  CHECK(cache.budgetCuts() == 1);
  CHECK(cache.budgetBytes() == (192 - 30) * layerBytes);
  CHECK(cache.bytes() == (192 - 30) * layerBytes);
  // The most recent layers stay; the oldest went.
  const uint64_t misses = cache.misses();
  cache.get(next - 1, 0, layerOf);
  cache.get(0, 0, layerOf);
  CHECK(cache.misses() == misses + 1);
  // Memory back: the budget stays where it is.
  available = size_t(1) << 30;
  missMany(2 * WarpLayerCache::kMissesBetweenChecks);
  CHECK(cache.budgetCuts() == 1);
  CHECK(cache.budgetBytes() == (192 - 30) * layerBytes);
  // Nothing left at all: down to the floor, not to nothing.
  available = 0;
  missMany(2 * WarpLayerCache::kMissesBetweenChecks);
  CHECK(cache.budgetBytes() == floor);
  CHECK(cache.bytes() <= floor);
  CHECK(cache.bytes() > 0);
  CHECK(availableMemoryBytes().has_value());
}

TEST_CASE("greedy insertion picks, at every step, the sample an exhaustive search picks") {
  // An L-shaped floor, 7 x 6 samples 1 m apart (jittered, so that no two
  // insertions tie), the north-east quarter walled off; errors grow with
  // the distance to each reference and jump behind a wall.
  RegionPolygon polygon;
  polygon.outer = {{-0.5, -0.5}, {6.5, -0.5}, {6.5, 2.5}, {3.5, 2.5}, {3.5, 5.5}, {-0.5, 5.5}};
  const WalkableRegion region({polygon}, "L");
  std::vector<glm::dvec2> positions;
  for (const glm::dvec2& p : testing::unitGrid(7, 6)) {
    const glm::dvec2 jittered = p + 0.2 * glm::dvec2(std::sin(7.1 * p.x + 3.3 * p.y), std::cos(5.3 * p.x - 2.9 * p.y));
    if (region.contains(jittered)) positions.push_back(jittered);
  }
  REQUIRE(positions.size() > 25);
  const FormulaErrors::Formula formula = distanceAndSightErrors(positions, region);
  // Starting from three neighbouring samples in the south-west corner.
  const std::vector<int> start = {0, 1, 6};
  REQUIRE(ViewMesh::delaunay(positions, start, "test", &region).vertexCount() == 3);
  const int count = 12;

  // Exhaustive: every free sample's insertion scored from scratch; the
  // lowest mean error joins (the lower index on a tie).
  std::vector<int> expected, references = start;
  while (int(references.size()) < count) {
    int best = -1;
    double bestError = std::numeric_limits<double>::infinity();
    for (int c = 0; c < int(positions.size()); ++c) {
      if (std::find(references.begin(), references.end(), c) != references.end()) continue;
      std::vector<int> tried = references;
      tried.push_back(c);
      const std::optional<ViewMesh> mesh = ViewMesh::tryDelaunay(positions, tried, &region);
      if (!mesh) continue;
      const double error = meanError(*mesh, formula);
      if (error < bestError) best = c, bestError = error;
    }
    REQUIRE(best >= 0);
    expected.push_back(best);
    references.push_back(best);
  }

  for (const int priced : {0, 32}) {
    CAPTURE(priced);
    FormulaErrors errors(formula);
    RefinementOptions options;
    options.region = &region;
    options.pricedSamples = priced;
    const InsertionResult result = insertGreedily(positions, start, count, errors, options);
    CHECK(result.inserted == expected);
    REQUIRE(result.objectives.size() == expected.size());
    // The objective after each step is the mean error of that selection.
    std::vector<int> selection = start;
    for (size_t step = 0; step < expected.size(); ++step) {
      selection.push_back(result.inserted[step]);
      const ViewMesh mesh = ViewMesh::delaunay(positions, selection, "test", &region);
      CHECK(result.objectives[step] == doctest::Approx(meanError(mesh, formula)).epsilon(1e-12));
    }
    CHECK(ViewMesh(positions, result.triangles).vertexCount() == count);
  }
}

}  // namespace triwalk
