#include "core/selection/baselines.h"

#include "core/selection/selection.h"
#include "core/support/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>

namespace triwalk {

std::vector<int> latticeSelection(std::span<const glm::dvec2> positions, int count) {
  TRIWALK_CHECK(!positions.empty() && count >= 1, "a lattice needs positions and a count");
  glm::dvec2 lower(std::numeric_limits<double>::max()), upper(std::numeric_limits<double>::lowest());
  for (glm::dvec2 p : positions) lower = glm::min(lower, p), upper = glm::max(upper, p);
  const glm::dvec2 size = glm::max(upper - lower, glm::dvec2(1e-9));
  std::vector<int> best;
  // Lattices with k intervals along the longer side, square cells, from
  // coarse to fine; stop once they overshoot count by half.
  const double longer = std::max(size.x, size.y);
  for (int k = 1; k <= int(positions.size()); ++k) {
    const double cell = longer / double(k);
    const int columns = int(std::lround(size.x / cell)) + 1, rows = int(std::lround(size.y / cell)) + 1;
    std::vector<int> snapped;
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < columns; ++c) {
        const glm::dvec2 node = lower + glm::dvec2(columns > 1 ? size.x * c / (columns - 1) : 0.5 * size.x,
                                                   rows > 1 ? size.y * r / (rows - 1) : 0.5 * size.y);
        int nearest = 0;
        for (int i = 1; i < int(positions.size()); ++i) {
          if (glm::length(positions[size_t(i)] - node) < glm::length(positions[size_t(nearest)] - node)) nearest = i;
        }
        snapped.push_back(nearest);
      }
    }
    std::sort(snapped.begin(), snapped.end());
    snapped.erase(std::unique(snapped.begin(), snapped.end()), snapped.end());
    if (best.empty() || std::abs(int(snapped.size()) - count) < std::abs(int(best.size()) - count)) best = snapped;
    if (int(snapped.size()) > count + count / 2) break;
  }
  return best;
}

namespace {

// Every sx-th column and sy-th row of a clipped lattice, from offsets
// (ox, oy): of all strides with a spacing ratio up to 2 and all offsets,
// the one scoring lowest on three times the relative count mismatch plus
// the log of the stride ratio (ties: smaller strides, then offsets) whose
// triangulation keeps a triangle inside the region. In a level of
// corridors a coarse sub-lattice can have none (every triangle crosses a
// wall), and a baseline without a triangle serves no probe; if no
// sub-lattice has one, the lowest score (the caller reports the region).
std::vector<int> subLatticeSelection(const std::map<std::pair<int, int>, int>& grid, int count,
                                     const std::vector<glm::dvec2>& positions, const WalkableRegion& region) {
  int columns = 0, rows = 0;
  for (const auto& [cell, sample] : grid) columns = std::max(columns, cell.first + 1), rows = std::max(rows, cell.second + 1);
  std::vector<int> best, lowest;  // the best usable one; the lowest score of those without a triangle
  double bestUsableScore = std::numeric_limits<double>::max(), bestScore = bestUsableScore;
  // A stride pair keeps about one sample in sx * sy; far from count no
  // offset helps, so those are tried only if none near it keeps a triangle.
  for (const bool nearCount : {true, false}) {
    for (int sx = 1; sx <= columns; ++sx) {
      for (int sy = 1; sy <= rows; ++sy) {
        const double kept = double(grid.size()) / double(sx * sy);
        const bool near = kept <= 3.0 * count && 3.0 * kept >= count;
        if (sx > 2 * sy || sy > 2 * sx || near != nearCount) continue;
        for (int ox = 0; ox < sx; ++ox) {
          for (int oy = 0; oy < sy; ++oy) {
            int n = 0;
            for (const auto& [cell, sample] : grid) n += cell.first % sx == ox && cell.second % sy == oy;
            const double score =
                3.0 * std::abs(double(n - count)) / double(count) + std::abs(std::log(double(sx) / sy));
            if (n < 3 || score >= bestUsableScore) continue;
            std::vector<int> candidate;
            for (const auto& [cell, sample] : grid) {
              if (cell.first % sx == ox && cell.second % sy == oy) candidate.push_back(sample);
            }
            std::sort(candidate.begin(), candidate.end());
            if (ViewMesh::tryDelaunay(positions, candidate, &region)) {
              bestUsableScore = score;
              best = std::move(candidate);
            } else if (score < bestScore) {
              bestScore = score;
              lowest = std::move(candidate);
            }
          }
        }
      }
    }
    if (!best.empty()) break;
  }
  return best.empty() ? lowest : best;
}

}  // namespace

std::vector<int> uniformSelection(const Dataset& dataset, int count) {
  std::map<std::pair<int, int>, int> grid;  // (path, step) -> sample index
  int paths = 0, steps = 0;
  bool onPaths = true;
  for (int i = 0; i < dataset.sampleCount(); ++i) {
    const ViewRecord& sample = dataset.sample(i);
    onPaths &= sample.path >= 0 && sample.step >= 0;
    if (!onPaths) break;
    grid[{sample.path, sample.step}] = i;
    paths = std::max(paths, sample.path + 1);
    steps = std::max(steps, sample.step + 1);
  }
  if (!onPaths || int(grid.size()) != dataset.sampleCount()) return latticeSelection(samplePositions(dataset), count);
  if (int(grid.size()) != paths * steps || paths < 2 || steps < 2) {
    return subLatticeSelection(grid, count, samplePositions(dataset), dataset.walkableRegion());
  }
  // Spacing of the dense grid along both axes, from the first path and step.
  const glm::dvec2 origin(dataset.sample(grid.at({0, 0})).position);
  const double pathSpan = glm::length(glm::dvec2(dataset.sample(grid.at({paths - 1, 0})).position) - origin);
  const double stepSpan = glm::length(glm::dvec2(dataset.sample(grid.at({0, steps - 1})).position) - origin);
  // The grid closest to count samples with the most even spacing: three
  // times the relative count mismatch plus the log of the spacing ratio.
  // On a 10 x 5 m area, 21 samples give 7 x 3 (as in the paper) and 22
  // give 6 x 4 (24), not a degenerate 11 x 2.
  int bestPaths = 2, bestSteps = 2;
  double bestScore = std::numeric_limits<double>::max();
  for (int p = 2; p <= paths; ++p) {
    for (int s = 2; s <= steps; ++s) {
      const double unevenness = std::abs(std::log((pathSpan / (p - 1)) / (stepSpan / (s - 1))));
      const double score = 3.0 * std::abs(double(p * s - count)) / double(count) + unevenness;
      if (score < bestScore) bestScore = score, bestPaths = p, bestSteps = s;
    }
  }
  std::vector<int> selection;
  for (int i = 0; i < bestPaths; ++i) {
    const int path = int(std::lround(double(i) * (paths - 1) / (bestPaths - 1)));
    for (int j = 0; j < bestSteps; ++j) {
      const int step = int(std::lround(double(j) * (steps - 1) / (bestSteps - 1)));
      selection.push_back(grid.at({path, step}));
    }
  }
  std::sort(selection.begin(), selection.end());
  return selection;
}

std::vector<int> kMedoidsSelection(std::span<const glm::dvec2> positions, int count) {
  const int n = int(positions.size());
  TRIWALK_CHECK(count >= 1 && count <= n, "k-medoids needs 1 <= k <= n");
  // Start: the sample nearest the centroid, then farthest-point picks.
  glm::dvec2 centroid(0.0);
  for (glm::dvec2 p : positions) centroid += p / double(n);
  std::vector<int> medoids;
  int first = 0;
  for (int i = 1; i < n; ++i) {
    if (glm::length(positions[size_t(i)] - centroid) < glm::length(positions[size_t(first)] - centroid)) first = i;
  }
  medoids.push_back(first);
  std::vector<double> nearest(size_t(n), std::numeric_limits<double>::max());
  while (int(medoids.size()) < count) {
    int farthest = -1;
    for (int i = 0; i < n; ++i) {
      nearest[size_t(i)] = std::min(nearest[size_t(i)], glm::length(positions[size_t(i)] - positions[size_t(medoids.back())]));
      if (farthest < 0 || nearest[size_t(i)] > nearest[size_t(farthest)]) farthest = i;
    }
    medoids.push_back(farthest);
  }

  return refineMedoids(n, std::move(medoids),
                       [&](int a, int b) { return glm::length(positions[size_t(a)] - positions[size_t(b)]); });
}

std::vector<int> refineMedoids(int n, std::vector<int> medoids, const std::function<double(int, int)>& distance) {
  const int count = int(medoids.size());
  std::vector<int> assignment(size_t(n), -1);
  for (int iteration = 0; iteration < 100; ++iteration) {
    bool changed = false;
    for (int i = 0; i < n; ++i) {
      int best = 0;
      for (int k = 1; k < count; ++k) {
        if (distance(i, medoids[size_t(k)]) < distance(i, medoids[size_t(best)])) best = k;
      }
      changed |= assignment[size_t(i)] != best;
      assignment[size_t(i)] = best;
    }
    for (int k = 0; k < count; ++k) {
      int bestMember = medoids[size_t(k)];
      double bestSum = std::numeric_limits<double>::max();
      for (int candidate = 0; candidate < n; ++candidate) {
        if (assignment[size_t(candidate)] != k) continue;
        double sum = 0.0;
        for (int member = 0; member < n; ++member) {
          if (assignment[size_t(member)] == k) sum += distance(member, candidate);
        }
        if (sum < bestSum) bestSum = sum, bestMember = candidate;
      }
      changed |= bestMember != medoids[size_t(k)];
      medoids[size_t(k)] = bestMember;
    }
    if (!changed) break;
  }
  std::sort(medoids.begin(), medoids.end());
  return medoids;
}

std::vector<int> randomSelection(int sampleCount, int count, unsigned seed) {
  TRIWALK_CHECK(count >= 0 && count <= sampleCount, "random selection larger than the data set");
  std::vector<int> order(static_cast<size_t>(sampleCount));
  for (int i = 0; i < sampleCount; ++i) order[size_t(i)] = i;
  // Fisher-Yates with the engine's raw output, the same on every platform.
  std::mt19937 engine(seed);
  for (int i = sampleCount - 1; i > 0; --i) std::swap(order[size_t(i)], order[size_t(engine() % unsigned(i + 1))]);
  order.resize(size_t(count));
  std::sort(order.begin(), order.end());
  return order;
}

}  // namespace triwalk
