#include "core/selection/walking_distances.h"

#include "core/selection/baselines.h"
#include "core/support/errors.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace triwalk {

namespace {

constexpr float kUnreachable = std::numeric_limits<float>::infinity();

// Edges reach this many times the median distance to the nearest other
// sample: far enough that paths across open floor run nearly straight.
constexpr double kEdgeReach = 3.0;

double medianNearestDistance(std::span<const glm::dvec2> positions) {
  std::vector<double> nearest;
  for (size_t i = 0; i < positions.size(); ++i) {
    double best = std::numeric_limits<double>::max();
    for (size_t j = 0; j < positions.size(); ++j) {
      if (j != i) best = std::min(best, glm::length(positions[i] - positions[j]));
    }
    nearest.push_back(best);
  }
  std::nth_element(nearest.begin(), nearest.begin() + std::ptrdiff_t(nearest.size() / 2), nearest.end());
  return nearest[nearest.size() / 2];
}

}  // namespace

WalkingDistances::WalkingDistances(std::span<const glm::dvec2> positions, const WalkableRegion& region)
    : count_(int(positions.size())), distances_(positions.size() * positions.size(), kUnreachable) {
  TRIWALK_CHECK(positions.size() >= 2, "walking distances need two samples");
  const double reach = kEdgeReach * medianNearestDistance(positions);
  struct Edge {
    int to;
    float length;
  };
  std::vector<std::vector<Edge>> edges(positions.size());
  tbb::parallel_for(size_t(0), positions.size(), [&](size_t i) {
    for (size_t j = 0; j < positions.size(); ++j) {
      const double length = glm::length(positions[i] - positions[j]);
      if (j != i && length <= reach && (region.empty() || region.containsSegment(positions[i], positions[j]))) {
        edges[i].push_back({int(j), float(length)});
      }
    }
  });
  // Dijkstra from every sample, each into its own row.
  tbb::parallel_for(0, count_, [&](int source) {
    float* row = &distances_[size_t(source) * size_t(count_)];
    using Entry = std::pair<float, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    row[source] = 0.0f;
    queue.push({0.0f, source});
    while (!queue.empty()) {
      const auto [distance, at] = queue.top();
      queue.pop();
      if (distance > row[at]) continue;
      for (const Edge& edge : edges[size_t(at)]) {
        const float through = distance + edge.length;
        if (through < row[edge.to]) {
          row[edge.to] = through;
          queue.push({through, edge.to});
        }
      }
    }
  });
}

int WalkingDistances::mostCentral() const {
  int best = 0;
  double bestSum = std::numeric_limits<double>::max();
  size_t bestReached = 0;
  for (int i = 0; i < count_; ++i) {
    double sum = 0.0;
    size_t reached = 0;
    for (int j = 0; j < count_; ++j) {
      if ((*this)(i, j) < kUnreachable) sum += (*this)(i, j), ++reached;
    }
    // The largest part of the region first, then the least sum within it.
    if (reached > bestReached || (reached == bestReached && sum < bestSum)) best = i, bestSum = sum, bestReached = reached;
  }
  return best;
}

std::vector<std::pair<int, float>> farthestPointOrder(const WalkingDistances& distances, int count) {
  const int n = distances.count();
  TRIWALK_CHECK(count >= 1 && count <= n, "farthest-point sampling needs 1 <= k <= n");
  std::vector<std::pair<int, float>> picks = {{distances.mostCentral(), kUnreachable}};
  std::vector<float> nearest(size_t(n), kUnreachable);
  std::vector<bool> chosen(size_t(n), false);
  chosen[size_t(picks[0].first)] = true;
  while (int(picks.size()) < count) {
    int farthest = -1;
    for (int i = 0; i < n; ++i) {
      nearest[size_t(i)] = std::min(nearest[size_t(i)], distances(picks.back().first, i));
      if (chosen[size_t(i)]) continue;
      if (farthest < 0 || nearest[size_t(i)] > nearest[size_t(farthest)]) farthest = i;
    }
    chosen[size_t(farthest)] = true;
    picks.push_back({farthest, nearest[size_t(farthest)]});
  }
  return picks;
}

std::vector<int> farthestPointSelection(const WalkingDistances& distances, int count) {
  std::vector<int> samples;
  for (const auto& [sample, distance] : farthestPointOrder(distances, count)) samples.push_back(sample);
  std::sort(samples.begin(), samples.end());
  return samples;
}

std::vector<int> regionUniformSelection(std::vector<int> lattice, const WalkingDistances& distances, int count) {
  const int n = distances.count();
  TRIWALK_CHECK(count >= 1 && count <= n, "the region-aware uniform baseline needs 1 <= count <= samples");
  std::sort(lattice.begin(), lattice.end());
  lattice.erase(std::unique(lattice.begin(), lattice.end()), lattice.end());
  std::vector<char> chosen(size_t(n), 0);
  for (int s : lattice) chosen[size_t(s)] = 1;
  // Walking distance from each sample to its nearest chosen one.
  std::vector<float> nearest(size_t(n), std::numeric_limits<float>::infinity());
  for (int i = 0; i < n; ++i) {
    for (int s : lattice) nearest[size_t(i)] = std::min(nearest[size_t(i)], distances(i, s));
  }
  while (int(lattice.size()) < count) {
    int farthest = -1;
    for (int i = 0; i < n; ++i) {
      if (!chosen[size_t(i)] && (farthest < 0 || nearest[size_t(i)] > nearest[size_t(farthest)])) farthest = i;
    }
    chosen[size_t(farthest)] = 1;
    lattice.push_back(farthest);
    for (int i = 0; i < n; ++i) nearest[size_t(i)] = std::min(nearest[size_t(i)], distances(i, farthest));
  }
  while (int(lattice.size()) > count) {
    // The chosen sample with the nearest other chosen one.
    size_t redundant = 0;
    float redundantDistance = std::numeric_limits<float>::infinity();
    for (size_t a = 0; a < lattice.size(); ++a) {
      float closest = std::numeric_limits<float>::infinity();
      for (size_t b = 0; b < lattice.size(); ++b) {
        if (a != b) closest = std::min(closest, distances(lattice[a], lattice[b]));
      }
      if (closest <= redundantDistance) redundantDistance = closest, redundant = a;
    }
    lattice.erase(lattice.begin() + ptrdiff_t(redundant));
  }
  std::sort(lattice.begin(), lattice.end());
  return lattice;
}

std::vector<int> geodesicKMedoidsSelection(const WalkingDistances& distances, int count) {
  const int n = distances.count();
  std::vector<int> medoids;
  for (const auto& [sample, distance] : farthestPointOrder(distances, count)) medoids.push_back(sample);
  // A sample no medoid reaches costs the same whichever it is assigned to,
  // so sums stay finite: unreachable counts as a large finite distance.
  auto cost = [&](int a, int b) {
    const float d = distances(a, b);
    return d < kUnreachable ? double(d) : 1e12;
  };
  return refineMedoids(n, std::move(medoids), cost);
}

}  // namespace triwalk
