#pragma once
// When a decimation stops: at a count of references, or before a collapse
// whose error exceeds a threshold (the paper's), whichever comes first.

#include "core/selection/collapse/collapse_log.h"

#include <algorithm>
#include <vector>

namespace triwalk {

struct StopRule {
  double maxError = 0.0;  // <= 0: no threshold
  int targetSamples = 0;  // 0: no target

  bool refuses(double error) const { return maxError > 0.0 && error > maxError; }
  bool reached(int countedReferences) const { return targetSamples > 0 && countedReferences <= targetSamples; }

  // For the time left: the collapses to the target count, or, under a
  // threshold, until the error reaches it at the pace of the last 32.
  size_t remainingCollapses(int countedReferences, const std::vector<Collapse>& log) const {
    const int floorCount = std::max(3, targetSamples);
    size_t remaining = size_t(std::max(0, countedReferences - floorCount));
    const size_t window = 32;
    if (maxError > 0.0 && log.size() > window) {
      const double rise = log.back().error - log[log.size() - 1 - window].error;
      if (rise > 0.0) {
        const double toThreshold = std::max(0.0, maxError - log.back().error);
        remaining = std::min(remaining, size_t(toThreshold / rise * double(window)) + 1);
      }
    }
    return remaining;
  }
};

}  // namespace triwalk
