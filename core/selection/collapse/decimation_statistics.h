#pragma once
// What a decimation counted, for its report and the tests.

#include <cstdint>

namespace triwalk {

struct DecimationStatistics {
  uint64_t errorsComputed = 0;  // triangle (or served-sample) errors evaluated
  uint64_t cacheHits = 0;       // errors served from the cache
  uint64_t staleEntriesSkipped = 0;
  uint64_t edgesCosted = 0;
  uint64_t collapseChecksFailed = 0;  // popped entries whose cost had changed
  // Last-resort searches that found a collapse taking a reference off a
  // straight stretch of the boundary; in a run of step() each is one such
  // collapse.
  uint64_t straightStretchSearches = 0;
  // Last-resort searches, after those, that found a reference to remove
  // with all its triangles (PlacementKind::Removal).
  uint64_t removals = 0;
};

}  // namespace triwalk
