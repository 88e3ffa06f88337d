#include "core/selection/collapse/centroid_cost.h"

#include "core/support/progress.h"

#include <set>
#include <span>

namespace triwalk {

CentroidCost::CentroidCost(const CollapseMesh& mesh, TriangleErrorSource& errors, bool areaWeighted,
                           DecimationStatistics& statistics)
    : mesh_(mesh), errors_(errors), areaWeighted_(areaWeighted), statistics_(statistics) {}

void CentroidCost::ensureErrors(const std::vector<const CollapsePlan*>& plans, ProgressReporter* progress) {
  std::vector<Triangle> missing;
  std::set<uint64_t> queued;
  for (const CollapsePlan* plan : plans) {
    for (const Triangle& t : plan->added) {
      const uint64_t key = triangleKey(t);
      if (cache_.count(key) || !queued.insert(key).second) {
        ++statistics_.cacheHits;
        continue;
      }
      missing.push_back(t);
    }
  }
  if (missing.empty()) return;
  // Progress is shown for the first costing, thousands of errors.
  const std::vector<double> computed =
      computeInChunks(std::span<const Triangle>(missing), progress,
                      [&](std::span<const Triangle> batch, std::span<double> batchErrors) {
                        errors_.computeErrors(batch, batchErrors);
                      });
  for (size_t i = 0; i < missing.size(); ++i) cache_[triangleKey(missing[i])] = computed[i];
  statistics_.errorsComputed += missing.size();
}

// The same mean ranks the collapse and meets the threshold.
CostAndError CentroidCost::price(const CollapsePlan& plan) const {
  double sum = 0.0, weightSum = 0.0;
  for (const Triangle& t : plan.added) {
    const glm::dvec2 a = mesh_.position(t[0]), b = mesh_.position(t[1]), c = mesh_.position(t[2]);
    const double weight = areaWeighted_ ? 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) : 1.0;
    sum += weight * cache_.at(triangleKey(t));
    weightSum += weight;
  }
  const double mean = sum / weightSum;
  return {mean, mean};
}

}  // namespace triwalk
