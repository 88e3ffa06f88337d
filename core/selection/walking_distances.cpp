#include "core/selection/walking_distances.h"

#include "core/geometry/view_mesh.h"
#include "core/selection/baselines.h"
#include "core/support/errors.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
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

namespace {

// The region-aware uniform baseline's working set: chosen samples, those
// that must stay (a view given a triangle, and the samples that gave it),
// and those that may never join (a view no triangle could hold).
class RegionUniform {
public:
  RegionUniform(const WalkingDistances& distances, std::span<const glm::dvec2> positions, const WalkableRegion& region)
      : distances_(distances),
        positions_(positions.begin(), positions.end()),
        region_(region),
        protected_(positions.size(), 0),
        excluded_(positions.size(), 0) {}

  std::vector<int> select(std::vector<int> lattice, int count) {
    std::sort(lattice.begin(), lattice.end());
    lattice.erase(std::unique(lattice.begin(), lattice.end()), lattice.end());
    chosen_ = std::move(lattice);
    fillTo(count);
    trimTo(count);
    // Each round protects a sample for the first time or excludes one for
    // good, so there are at most 2n rounds.
    while (chosen_.size() >= 3) {
      const std::vector<int> dropped = droppedSamples();
      if (dropped.empty()) break;
      const int lone = dropped.front();
      if (!protected_[size_t(lone)] && giveTriangle(lone, count)) {
        trimTo(count);
      } else {
        excluded_[size_t(lone)] = 1;
        protected_[size_t(lone)] = 0;
        std::erase(chosen_, lone);
        fillTo(count);
      }
    }
    std::sort(chosen_.begin(), chosen_.end());
    return chosen_;
  }

private:
  // At most this many samples join to give a lone view a triangle: two
  // make one with it; the third where the nearest two lie on a line with it.
  static constexpr int kMaxCompanions = 3;

  // The chosen samples that no triangle inside the region keeps, ascending.
  std::vector<int> droppedSamples() const {
    const std::optional<ViewMesh> mesh = ViewMesh::tryDelaunay(positions_, chosen_, &region_);
    const std::vector<int> kept = mesh ? mesh->vertices() : std::vector<int>();
    std::vector<int> dropped;
    for (int s : chosen_) {
      if (!std::binary_search(kept.begin(), kept.end(), s)) dropped.push_back(s);
    }
    std::sort(dropped.begin(), dropped.end());
    return dropped;
  }

  bool isKept(int sample) const {
    const std::vector<int> dropped = droppedSamples();
    return !std::binary_search(dropped.begin(), dropped.end(), sample);
  }

  int protectedCount() const { return int(std::count(protected_.begin(), protected_.end(), 1)); }

  bool isFree(int sample) const {
    return !excluded_[size_t(sample)] && std::find(chosen_.begin(), chosen_.end(), sample) == chosen_.end();
  }

  // The samples nearest a lone view by walking join, one at a time, until
  // it is kept; then it and they stay, if the samples that stay still fit
  // the count. Otherwise they leave again.
  bool giveTriangle(int lone, int count) {
    std::vector<int> companions;
    while (int(companions.size()) < kMaxCompanions) {
      int nearest = -1;
      for (int i = 0; i < distances_.count(); ++i) {
        if (!isFree(i) || !std::isfinite(distances_(lone, i))) continue;
        if (nearest < 0 || distances_(lone, i) < distances_(lone, nearest)) nearest = i;
      }
      if (nearest < 0) break;
      companions.push_back(nearest);
      chosen_.push_back(nearest);
      if (protectedCount() + 1 + int(companions.size()) > count) break;
      if (isKept(lone)) {
        protected_[size_t(lone)] = 1;
        for (int c : companions) protected_[size_t(c)] = 1;
        return true;
      }
    }
    for (int c : companions) std::erase(chosen_, c);
    return false;
  }

  // While short, the free sample farthest from its nearest chosen one joins
  // (the lower index on a tie).
  void fillTo(int count) {
    const int n = distances_.count();
    std::vector<float> nearest(size_t(n), std::numeric_limits<float>::infinity());
    for (int i = 0; i < n; ++i) {
      for (int s : chosen_) nearest[size_t(i)] = std::min(nearest[size_t(i)], distances_(i, s));
    }
    std::vector<char> isChosen(size_t(n), 0);
    for (int s : chosen_) isChosen[size_t(s)] = 1;
    while (int(chosen_.size()) < count) {
      int farthest = -1;
      for (int i = 0; i < n; ++i) {
        if (isChosen[size_t(i)] || excluded_[size_t(i)]) continue;
        if (farthest < 0 || nearest[size_t(i)] > nearest[size_t(farthest)]) farthest = i;
      }
      if (farthest < 0) break;
      isChosen[size_t(farthest)] = 1;
      chosen_.push_back(farthest);
      for (int i = 0; i < n; ++i) nearest[size_t(i)] = std::min(nearest[size_t(i)], distances_(i, farthest));
    }
  }

  // While over, the chosen sample nearest another chosen one leaves, of
  // those not protected (the later in index order on a tie).
  void trimTo(int count) {
    std::sort(chosen_.begin(), chosen_.end());
    while (int(chosen_.size()) > count) {
      std::optional<size_t> redundant;
      float redundantDistance = std::numeric_limits<float>::infinity();
      for (size_t a = 0; a < chosen_.size(); ++a) {
        if (protected_[size_t(chosen_[a])]) continue;
        float closest = std::numeric_limits<float>::infinity();
        for (size_t b = 0; b < chosen_.size(); ++b) {
          if (a != b) closest = std::min(closest, distances_(chosen_[a], chosen_[b]));
        }
        if (!redundant || closest <= redundantDistance) redundantDistance = closest, redundant = a;
      }
      if (!redundant) return;
      chosen_.erase(chosen_.begin() + ptrdiff_t(*redundant));
    }
  }

  const WalkingDistances& distances_;
  std::vector<glm::dvec2> positions_;
  const WalkableRegion& region_;
  std::vector<int> chosen_;
  std::vector<char> protected_, excluded_;
};

}  // namespace

std::vector<int> regionUniformSelection(std::vector<int> lattice, const WalkingDistances& distances,
                                        std::span<const glm::dvec2> positions, const WalkableRegion& region, int count) {
  TRIWALK_CHECK(count >= 3 && count <= distances.count() && size_t(distances.count()) == positions.size(),
                "the region-aware uniform baseline needs 3 <= count <= samples, a position for each");
  return RegionUniform(distances, positions, region).select(std::move(lattice), count);
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
