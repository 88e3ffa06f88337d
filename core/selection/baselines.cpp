#include "core/selection/baselines.h"

#include "core/support/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>

namespace triwalk {

std::vector<int> uniformSelection(const Dataset& dataset, int count) {
  std::map<std::pair<int, int>, int> grid;  // (path, step) -> sample index
  int paths = 0, steps = 0;
  for (int i = 0; i < dataset.sampleCount(); ++i) {
    const ViewRecord& sample = dataset.sample(i);
    if (sample.path < 0 || sample.step < 0) {
      throw InputError(dataset.manifestPath().string(), "the uniform baseline needs each sample's path and step");
    }
    grid[{sample.path, sample.step}] = i;
    paths = std::max(paths, sample.path + 1);
    steps = std::max(steps, sample.step + 1);
  }
  if (int(grid.size()) != paths * steps) {
    throw InputError(dataset.manifestPath().string(), "the uniform baseline needs a complete grid of paths and steps");
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

  std::vector<int> assignment(size_t(n), -1);
  for (int iteration = 0; iteration < 100; ++iteration) {
    bool changed = false;
    for (int i = 0; i < n; ++i) {
      int best = 0;
      for (int k = 1; k < count; ++k) {
        if (glm::length(positions[size_t(i)] - positions[size_t(medoids[size_t(k)])]) <
            glm::length(positions[size_t(i)] - positions[size_t(medoids[size_t(best)])])) {
          best = k;
        }
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
          if (assignment[size_t(member)] == k) sum += glm::length(positions[size_t(member)] - positions[size_t(candidate)]);
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
