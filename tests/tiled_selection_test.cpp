// Tiled selection's pieces on exact inputs: the cut into cores, margins and
// seam bands, and the frozen samples a seam pass relies on (a frozen
// reference never leaves, a frozen free sample is never taken), checked
// against the same runs without them.

#include "core/geometry/view_mesh.h"
#include "core/selection/edge_collapse_decimator.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection_refinement.h"
#include "core/selection/tile_partition.h"
#include "core/selection/tiled_selection.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace triwalk {
namespace {

// Errors that grow with the distance from the nearest reference to the
// destination: a decimation removes references where they crowd.
class NearestReferenceErrors final : public ReconstructionErrorSource {
public:
  explicit NearestReferenceErrors(const std::vector<glm::dvec2>& positions) : positions_(positions) {}
  void computeReconstructionErrors(std::span<const SampleReconstruction> requests, std::span<double> errors) override {
    for (size_t i = 0; i < requests.size(); ++i) {
      double nearest = 1e9;
      for (int r : requests[i].references) {
        nearest = std::min(nearest, glm::length(positions_[size_t(r)] - positions_[size_t(requests[i].destination)]));
      }
      errors[i] = nearest;
    }
  }

private:
  const std::vector<glm::dvec2>& positions_;
};

// Every sample of positions triangulated.
ViewMesh denseMesh(const std::vector<glm::dvec2>& positions) {
  std::vector<int> everything(positions.size());
  for (size_t i = 0; i < everything.size(); ++i) everything[i] = int(i);
  return ViewMesh::delaunay(positions, everything, "test");
}

// 1 for the samples left of x = 3.5.
std::vector<char> leftHalf(const std::vector<glm::dvec2>& positions) {
  std::vector<char> mask(positions.size(), 0);
  for (size_t i = 0; i < positions.size(); ++i) mask[i] = positions[i].x < 3.5 ? 1 : 0;
  return mask;
}

struct Decimated {
  ViewMesh mesh;
  StopReason stop;
};

// dense decimated by NearestReferenceErrors to the options' target, with no error threshold.
Decimated decimateToTarget(const ViewMesh& dense, const std::vector<glm::dvec2>& positions, DecimationOptions options) {
  NearestReferenceErrors errors(positions);
  options.maxError = 0.0;
  EdgeCollapseDecimator decimator(dense, DecimationErrors{nullptr, &errors}, options);
  const StopReason stop = decimator.run();
  return {decimator.mesh(), stop};
}

}  // namespace

TEST_CASE("cores: median splits into equal counts across the longer side, every sample in one core, none on a border") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(16, 4);  // 64 samples, 15 m x 3 m
  const std::vector<TileCore> cores = splitIntoCores(positions, 0.0, {.count = 4});
  REQUIRE(cores.size() == 4);
  std::vector<int> seen;
  for (const TileCore& core : cores) {
    CHECK(core.members.size() == 16);  // cut across x three times: 4 columns each
    for (int i : core.members) {
      const glm::dvec2 p = positions[size_t(i)];
      CHECK(p.x > core.lower.x - 1e-12);
      CHECK(p.x < core.upper.x + 1e-12);
      for (const TileCore& other : cores) {
        if (&other == &core) continue;
        // Halfway between lattice columns: never on another core's rectangle.
        CHECK(!(p.x >= other.lower.x && p.x <= other.upper.x && p.y >= other.lower.y && p.y <= other.upper.y));
      }
      seen.push_back(i);
    }
    CHECK(core.upper.y - core.lower.y == doctest::Approx(3.0));  // the short side was never cut
  }
  std::sort(seen.begin(), seen.end());
  std::vector<int> all(positions.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
  CHECK(seen == all);
  CHECK(cores[0].upper.x == doctest::Approx(3.5));
  CHECK(cores[1].upper.x == doctest::Approx(7.5));
  CHECK(cores[2].upper.x == doctest::Approx(11.5));

  // Three cores: the crowded half is split again, the other kept whole.
  const std::vector<TileCore> three = splitIntoCores(positions, 0.0, {.count = 3});
  REQUIRE(three.size() == 3);
  CHECK(three[0].members.size() == 16);
  CHECK(three[1].members.size() == 16);
  CHECK(three[2].members.size() == 32);
  // Samples that all share a position cannot be split: one core, not a loop.
  const std::vector<glm::dvec2> stacked(5, glm::dvec2(1.0, 1.0));
  CHECK(splitIntoCores(stacked, 0.0, {.count = 4}).size() == 1);
  CHECK(splitIntoCores(stacked, 0.0, {.mostTileSamples = 2}).size() == 1);
}

TEST_CASE("cores with a bound: the largest tile, margin included, is split until every tile holds at most the bound") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(16, 4);  // columns x = 0..15, 4 samples each
  auto tileSizes = [&](const std::vector<TileCore>& cores) {
    std::vector<size_t> sizes;
    for (const Tile& tile : tilesWithMargin(positions, cores, 1.0)) sizes.push_back(tile.samples.size());
    return sizes;
  };
  // 1 m of margin: a core of 4 columns inside the capture makes a tile of 6
  // (24 samples), at an end of 5. Halves (36 each), then the first half
  // (20, 24), then the second (24, 20): every tile within 24, four cores.
  const std::vector<TileCore> within24 = splitIntoCores(positions, 1.0, {.mostTileSamples = 24});
  CHECK(tileSizes(within24) == std::vector<size_t>{20, 24, 24, 20});
  // Within 23: the inner tiles of 24 are split again (a core of 2 columns
  // inside makes a tile of 4), the end ones of 20 are not.
  const std::vector<TileCore> within23 = splitIntoCores(positions, 1.0, {.mostTileSamples = 23});
  CHECK(tileSizes(within23) == std::vector<size_t>{20, 16, 16, 16, 16, 20});
  // Without margins the bound is the core's own count.
  CHECK(splitIntoCores(positions, 0.0, {.mostTileSamples = 16}).size() == 4);
  CHECK(splitIntoCores(positions, 0.0, {.mostTileSamples = 64}).size() == 1);
}

TEST_CASE("the margin is 4 refinement radii, and two reference spacings where a target count makes the references sparser") {
  // No target, or a target dense enough: the fixed margin.
  CHECK(tileMargin(1.5, 450, 0) == doctest::Approx(6.0));
  CHECK(tileMargin(1.5, 450, 90) == doctest::Approx(6.0));  // a fifth: two spacings are 3.4 radii
  // One reference for 20 samples of a grid of spacing 1 (radius sqrt 2):
  // an area of 20 each, neighbours sqrt(40 / sqrt 3) = 4.806 apart.
  CHECK(tileMargin(std::sqrt(2.0), 400, 20) == doctest::Approx(2.0 * std::sqrt(40.0 / std::sqrt(3.0))));
  // It grows as the square root of the samples per reference.
  CHECK(tileMargin(1.0, 8000, 100) == doctest::Approx(2.0 * tileMargin(1.0, 2000, 100)));
}

TEST_CASE("a tile holds its core and the samples within the margin of it, and the band is the core's samples near another core") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(16, 4);
  const std::vector<TileCore> cores = splitIntoCores(positions, 0.0, {.count = 4});
  const std::vector<Tile> tiles = tilesWithMargin(positions, cores, 1.0);
  REQUIRE(tiles.size() == 4);
  // Core 1 holds columns 4-7 (border at 3.5 and 7.5): within 1 m, columns 3 and 8 too.
  CHECK(tiles[1].samples.size() == 6 * 4);
  CHECK(tiles[0].samples.size() == 5 * 4);  // columns 0-4
  for (int i : tiles[1].samples) CHECK((positions[size_t(i)].x >= 3.0 && positions[size_t(i)].x <= 8.0));
  // Band 0.5 m: columns 4 and 7 of core 1 (0.5 m from the borders), column 3 of core 0.
  const std::vector<int> band1 = bandMembers(positions, cores[1], 0.5, cores);
  CHECK(band1.size() == 8);
  for (int i : band1) CHECK((positions[size_t(i)].x == 4.0 || positions[size_t(i)].x == 7.0));
  const std::vector<int> band0 = bandMembers(positions, cores[0], 0.5, cores);
  CHECK(band0.size() == 4);  // the capture's own edge (x = 0) is no seam
}

TEST_CASE("a tile's samples: all weighted by their share of the whole capture, the core counted and refined, the margin frozen and not judged") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(16, 4);
  const std::vector<Tile> tiles = tilesWithMargin(positions, splitIntoCores(positions, 0.0, {.count = 4}), 1.0);
  std::vector<double> captureWeights(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) captureWeights[i] = 1.0 + double(i);  // every sample its own
  const Tile& tile = tiles[1];  // core: columns 4-7; margin: columns 3 and 8
  SelectionSettings selection;
  assignTileRoles(tile, captureWeights, selection);
  REQUIRE(selection.decimation.sampleWeights.size() == tile.samples.size());
  REQUIRE(selection.refinement.sampleWeights.size() == tile.samples.size());
  REQUIRE(selection.refinement.frozen.size() == tile.samples.size());
  REQUIRE(selection.decimation.counted.size() == tile.samples.size());
  size_t margin = 0;
  for (size_t local = 0; local < tile.samples.size(); ++local) {
    const int sample = tile.samples[local];
    const bool inCore = positions[size_t(sample)].x >= 4.0 && positions[size_t(sample)].x <= 7.0;
    margin += inCore ? 0 : 1;
    CHECK(selection.decimation.sampleWeights[local] == captureWeights[size_t(sample)]);
    CHECK(selection.refinement.sampleWeights[local] == (inCore ? captureWeights[size_t(sample)] : 0.0));
    CHECK(selection.refinement.frozen[local] == (inCore ? 0 : 1));
    CHECK(selection.decimation.counted[local] == (inCore ? 1 : 0));
  }
  CHECK(margin == 2 * 4);
}

TEST_CASE("seam rounds: tiles whose steps do not reach each other share a round, and no two of a round do") {
  // Tile j's step changes its band and reads its tile; two steps may run at
  // once only when neither's band holds a sample of the other's tile.
  auto colouring = [](const std::vector<glm::dvec2>& positions, int count, double margin) {
    const std::vector<TileCore> cores = splitIntoCores(positions, 0.0, {.count = count});
    const std::vector<Tile> tiles = tilesWithMargin(positions, cores, margin);
    std::vector<std::vector<int>> bands;
    for (const TileCore& core : cores) bands.push_back(bandMembers(positions, core, 0.5, cores));
    const std::vector<int> colours = seamColours(tiles, bands, positions.size());
    for (size_t j = 0; j < tiles.size(); ++j) {
      for (size_t k = 0; k < tiles.size(); ++k) {
        if (j == k || colours[j] != colours[k]) continue;
        for (int s : bands[j]) CHECK(!std::binary_search(tiles[k].samples.begin(), tiles[k].samples.end(), s));
      }
    }
    return colours;
  };
  // A strip of 4 cores of 4 columns, bands of one column: with 1 m of
  // margin tile 2 (columns 7-12) holds nothing of band 0 (column 3), so
  // alternate tiles share a round.
  const std::vector<glm::dvec2> strip = testing::unitGrid(16, 4);
  CHECK(colouring(strip, 4, 1.0) == std::vector<int>{0, 1, 0, 1});
  // With 5 m of margin tile 0 reaches column 8, band 2's: every step reaches
  // the next but one, and only tiles 0 and 3 may share a round.
  CHECK(colouring(strip, 4, 5.0) == std::vector<int>{0, 1, 2, 0});
  // A 4 x 4 grid of cores: a band's corner sample lies in the diagonal
  // neighbour's margin, so four rounds, four steps each.
  const std::vector<int> grid = colouring(testing::unitGrid(16, 16), 16, 1.0);
  CHECK(*std::max_element(grid.begin(), grid.end()) == 3);
  for (int colour = 0; colour < 4; ++colour) CHECK(std::count(grid.begin(), grid.end(), colour) == 4);
}

TEST_CASE("a seam round takes out its share of the excess exactly, split by its bands' free references") {
  const auto removals = [](long excess, std::vector<long> free, long freeLeft) {
    return roundRemovals(excess, free, freeLeft);
  };
  // The last round takes all that is over: 3 split 5:5 is 2 and 1 (the
  // earlier step first on a tie), where rounding each step up took out 4.
  CHECK(removals(3, {5, 5}, 10) == std::vector<int>{2, 1});
  // A round with half the free references left takes half, rounded up,
  // by largest remainder: 7 * 6 / 12 = 3.5 -> 4, split 4:2 as 2.67 and
  // 1.33 -> 3 and 1.
  CHECK(removals(7, {4, 2}, 12) == std::vector<int>{3, 1});
  // No step is given more than its band holds: 5 of 1 + 9 (remainders
  // tied) is 1 and 4; 6 over with 3 free references left is all 3.
  CHECK(removals(5, {1, 9}, 10) == std::vector<int>{1, 4});
  CHECK(removals(6, {1, 2}, 3) == std::vector<int>{1, 2});
  // Nothing over the target, or nothing free: nothing taken.
  CHECK(removals(0, {4, 4}, 8) == std::vector<int>{0, 0});
  CHECK(removals(3, {0, 0}, 6) == std::vector<int>{0, 0});
}

TEST_CASE("a target counted over some samples: the decimation stops when those reach it, whatever the others hold") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(8, 6);
  const ViewMesh dense = denseMesh(positions);
  const std::vector<char> core = leftHalf(positions);  // 24 samples

  auto decimate = [&](const std::vector<char>& counted) {
    DecimationOptions options;
    options.targetSamples = 8;
    options.counted = counted;
    const Decimated decimated = decimateToTarget(dense, positions, options);
    CHECK(decimated.stop == StopReason::TargetReached);
    return decimated.mesh;
  };
  auto inCore = [&](const ViewMesh& mesh) {
    return std::count_if(mesh.vertices().begin(), mesh.vertices().end(), [&](int v) { return core[size_t(v)] != 0; });
  };
  const ViewMesh whole = decimate({});
  CHECK(whole.vertexCount() == 8);
  CHECK(inCore(whole) < 8);  // counted over everything, the core keeps only its part of the 8
  const ViewMesh counted = decimate(core);
  CHECK(inCore(counted) == 8);  // counted over the core, the core keeps 8
  CHECK(counted.vertexCount() > 8);
}

TEST_CASE("frozen samples: collapses never remove a frozen reference, and refinement never moves one or takes a frozen sample") {
  const std::vector<glm::dvec2> positions = testing::unitGrid(8, 6);
  const ViewMesh dense = denseMesh(positions);
  const std::vector<char> frozen = leftHalf(positions);

  auto decimate = [&](const std::vector<char>& mask) {
    DecimationOptions options;
    options.targetSamples = 10;
    options.frozen = mask;
    return decimateToTarget(dense, positions, options).mesh;
  };
  const ViewMesh free = decimate({});
  const ViewMesh partly = decimate(frozen);
  auto frozenKept = [&](const ViewMesh& mesh) {
    size_t kept = 0;
    for (int v : mesh.vertices()) kept += size_t(frozen[size_t(v)]);
    return kept;
  };
  const size_t frozenCount = size_t(std::count(frozen.begin(), frozen.end(), 1));
  CHECK(frozenKept(free) < frozenCount);     // without the mask, the left half loses references too
  CHECK(frozenKept(partly) == frozenCount);  // with it, every one stays
  CHECK(partly.vertexCount() < dense.vertexCount());  // and the right half was decimated

  NearestReferenceErrors errors(positions);
  RefinementOptions refinement{1.5, 8, {}, nullptr, {}};
  refinement.frozen = frozen;
  const RefinementResult refined = refineSelection(positions, partly.triangles(), errors, refinement);
  for (const Collapse& move : refined.moves) {
    CHECK(!frozen[size_t(move.first)]);
    CHECK(!frozen[size_t(move.placement)]);
  }
  std::set<int> after;
  for (const Triangle& t : refined.triangles) after.insert(t.begin(), t.end());
  for (size_t i = 0; i < positions.size(); ++i) {
    if (frozen[i]) CHECK(after.count(int(i)) == 1);
  }
  // Without the mask the same refinement moves references of the left half
  // (so the check above is not vacuous).
  const RefinementResult unmasked = refineSelection(positions, partly.triangles(), errors, {1.5, 8, {}, nullptr, {}});
  CHECK(std::any_of(unmasked.moves.begin(), unmasked.moves.end(),
                    [&](const Collapse& move) { return frozen[size_t(move.first)] || frozen[size_t(move.placement)]; }));
}

}  // namespace triwalk
