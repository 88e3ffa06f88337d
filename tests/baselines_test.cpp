// The baselines edge collapse is compared with.

#include "core/io/dataset.h"
#include "core/selection/baselines.h"
#include "core/selection/evaluation.h"
#include "core/selection/selection.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <set>

namespace triwalk {

TEST_CASE("uniform: a regular sub-grid of the capture paths with the corners, near the asked count") {
  testing::TemporaryDirectory directory;
  // 11 paths x 6 steps over 4 x 2 m: spacing 0.4 m both ways.
  testing::writeAnalyticDataset(directory.path(), 11, 6, 16, 0);
  const Dataset dataset = Dataset::open(directory.path());
  // 6 paths x 3 steps (spacing 0.8 x 1.0 m) is the even grid of 18; the
  // middle step is round(2.5) = 3.
  const std::vector<int> selection = uniformSelection(dataset, 18);
  REQUIRE(selection.size() == 18);
  std::set<std::pair<int, int>> grid;
  for (int s : selection) grid.insert({dataset.sample(s).path, dataset.sample(s).step});
  const std::set<std::pair<int, int>> expected = {{0, 0}, {0, 3}, {0, 5}, {2, 0}, {2, 3}, {2, 5}, {4, 0}, {4, 3}, {4, 5},
                                                  {6, 0}, {6, 3}, {6, 5}, {8, 0}, {8, 3}, {8, 5}, {10, 0}, {10, 3}, {10, 5}};
  CHECK(grid == expected);
}

TEST_CASE("uniform on a lattice clipped to an L-shaped region: a coarser sub-lattice of it, near the count") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory.path(), 11, 6, 16, 0);
  // Clip the 11 x 6 lattice to an L: no samples with path >= 6 and step >= 3.
  Manifest manifest = Dataset::open(directory.path()).manifest();
  std::erase_if(manifest.samples, [](const ViewRecord& s) { return s.path >= 6 && s.step >= 3; });
  for (size_t i = 0; i < manifest.samples.size(); ++i) manifest.samples[i].id = int(i);
  writeManifest(directory.path(), manifest);
  const Dataset dataset = Dataset::open(directory.path());
  REQUIRE(dataset.sampleCount() == 66 - 15);
  // Every second path and step from (0, 0): 6 x 3 minus the 3 x 1 the L
  // lacks, 15 samples, evenly spaced.
  const std::vector<int> selection = uniformSelection(dataset, 15);
  std::set<std::pair<int, int>> grid;
  for (int s : selection) grid.insert({dataset.sample(s).path, dataset.sample(s).step});
  const std::set<std::pair<int, int>> expected = {{0, 0}, {0, 2}, {0, 4}, {2, 0}, {2, 2}, {2, 4}, {4, 0}, {4, 2},
                                                  {4, 4}, {6, 0}, {6, 2}, {8, 0}, {8, 2}, {10, 0}, {10, 2}};
  CHECK(grid == expected);
}

TEST_CASE("uniform on a lattice clipped to a ring corridor: the nearest sub-lattice that keeps a triangle inside") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory.path(), 11, 6, 16, 0);
  // Keep the lattice's outer ring (one sample wide) and walk only there: a
  // corridor round a block, as a level's loop of corridors. Every triangle
  // of a coarser sub-lattice spans the block; only three neighbours round
  // a corner make one that stays in the corridor.
  Manifest manifest = Dataset::open(directory.path()).manifest();
  std::erase_if(manifest.samples,
                [](const ViewRecord& s) { return s.path > 0 && s.path < 10 && s.step > 0 && s.step < 5; });
  for (size_t i = 0; i < manifest.samples.size(); ++i) manifest.samples[i].id = int(i);
  glm::dvec2 lower(1e9), upper(-1e9);
  for (const ViewRecord& s : manifest.samples)
    lower = glm::min(lower, glm::dvec2(s.position)), upper = glm::max(upper, glm::dvec2(s.position));
  const double spacing = (upper.x - lower.x) / 10.0, margin = 0.5 * spacing, inset = 0.6 * spacing;
  RegionPolygon ring;
  ring.outer = {{lower.x - margin, lower.y - margin},
                {upper.x + margin, lower.y - margin},
                {upper.x + margin, upper.y + margin},
                {lower.x - margin, upper.y + margin}};
  ring.holes = {{{lower.x + inset, lower.y + inset},
                 {lower.x + inset, upper.y - inset},
                 {upper.x - inset, upper.y - inset},
                 {upper.x - inset, lower.y + inset}}};
  manifest.walkable = WalkableRegion({ring}, "ring");
  writeManifest(directory.path(), manifest);
  const Dataset dataset = Dataset::open(directory.path());
  REQUIRE(dataset.sampleCount() == 30);
  for (const int count : {4, 8, 12}) {
    CAPTURE(count);
    const std::vector<int> selection = uniformSelection(dataset, count);
    // Evaluable: its mesh keeps a triangle (no sub-lattice near these
    // counts has one; before, the baseline's mesh failed to build).
    CHECK(datasetMesh(dataset, selection, "uniform baseline").triangleCount() > 0);
    CHECK(uniformSelection(dataset, count) == selection);
  }
}

TEST_CASE("uniform without paths: a square lattice snapped to irregular samples, near the count, corners included") {
  // A 10 x 5 m area sampled irregularly: a jittered 0.5 m grid with every
  // seventh position missing (an imported capture has no paths).
  std::vector<glm::dvec2> positions;
  for (int x = 0; x <= 20; ++x) {
    for (int y = 0; y <= 10; ++y) {
      if ((x * 11 + y) % 7 == 3) continue;
      positions.emplace_back(0.5 * x + 0.1 * std::sin(1.7 * x + 2.3 * y), 0.5 * y + 0.1 * std::cos(2.9 * x + 1.1 * y));
    }
  }
  for (const int count : {8, 18, 32}) {
    CAPTURE(count);
    const std::vector<int> selection = latticeSelection(positions, count);
    CHECK(std::set<int>(selection.begin(), selection.end()).size() == selection.size());
    CHECK(std::abs(int(selection.size()) - count) <= count / 4 + 1);
    CHECK(latticeSelection(positions, count) == selection);
    // Spread like a lattice: every position has a selected sample within
    // about one cell of a lattice of that many nodes over the 50 m² (side
    // sqrt(50 / n)), so the corners are served too.
    const double cell = std::sqrt(50.0 / double(selection.size()));
    for (glm::dvec2 p : positions) {
      double nearest = 1e9;
      for (int s : selection) nearest = std::min(nearest, glm::length(p - positions[size_t(s)]));
      CHECK(nearest < 1.2 * cell);
    }
  }
}

TEST_CASE("k-medoids: k distinct samples spread over the area, the same every time") {
  std::vector<glm::dvec2> positions;
  for (int x = 0; x < 20; ++x) {
    for (int y = 0; y < 10; ++y) positions.emplace_back(0.5 * x, 0.5 * y);
  }
  const std::vector<int> medoids = kMedoidsSelection(positions, 8);
  REQUIRE(medoids.size() == 8);
  CHECK(std::set<int>(medoids.begin(), medoids.end()).size() == 8);
  CHECK(kMedoidsSelection(positions, 8) == medoids);
  // Every position is within 2 m of a medoid (8 clusters over 9.5 x 4.5 m;
  // a single cluster around the centre would leave corners 5.2 m away).
  for (glm::dvec2 p : positions) {
    double nearest = 1e9;
    for (int m : medoids) nearest = std::min(nearest, glm::length(p - positions[size_t(m)]));
    CHECK(nearest < 2.0);
  }
}

TEST_CASE("random: seeded, distinct, sorted") {
  const std::vector<int> a = randomSelection(100, 10, 7), b = randomSelection(100, 10, 7), c = randomSelection(100, 10, 8);
  CHECK(a == b);
  CHECK(a != c);
  CHECK(std::set<int>(a.begin(), a.end()).size() == 10);
  CHECK(std::is_sorted(a.begin(), a.end()));
}

TEST_CASE("paired comparison of probe errors: mean difference, its standard error, probes lower") {
  // Differences -1, 0, 1, 2: mean 0.5; sample deviation sqrt(5/3); standard
  // error sqrt(5/3) / 2; the candidate is lower at the first probe only.
  const PairedComparison paired = compareProbeErrors({1.0, 2.0, 3.0, 4.0}, {2.0, 2.0, 2.0, 2.0});
  CHECK(paired.meanDifference == doctest::Approx(0.5));
  CHECK(paired.standardError == doctest::Approx(std::sqrt(5.0 / 3.0) / 2.0));
  CHECK(paired.candidateLower == 1);
  // A constant offset is certain: no spread, no standard error.
  const PairedComparison offset = compareProbeErrors({1.0, 2.0, 3.0}, {1.5, 2.5, 3.5});
  CHECK(offset.meanDifference == doctest::Approx(-0.5));
  CHECK(offset.standardError == doctest::Approx(0.0));
  CHECK(offset.candidateLower == 3);
}

TEST_CASE("views for an error: interpolated where a method's count curve crosses it, bounded outside it") {
  const std::vector<std::pair<int, double>> curve = {{10, 2.0}, {20, 1.0}, {40, 0.5}};
  // 1.5 lies halfway from 2.0 to 1.0: halfway from 10 to 20 views.
  const ViewsForError halfway = viewsForError(curve, 1.5);
  CHECK(halfway.bound == ViewsForError::Bound::Interpolated);
  CHECK(halfway.views == doctest::Approx(15.0));
  // On the second segment: 0.8 is 40% of the way from 1.0 to 0.5.
  CHECK(viewsForError(curve, 0.8).views == doctest::Approx(28.0));
  // Exactly a point's error: that point's count.
  CHECK(viewsForError(curve, 1.0).views == doctest::Approx(20.0));
  // Already there at the first count; never there.
  const ViewsForError first = viewsForError(curve, 3.0), never = viewsForError(curve, 0.4);
  CHECK(first.bound == ViewsForError::Bound::AtMost);
  CHECK(formatViews(first) == "<= 10");
  CHECK(never.bound == ViewsForError::Bound::MoreThan);
  CHECK(formatViews(never) == "> 40");
  CHECK(formatViews(halfway) == "15.0");
}

}  // namespace triwalk
