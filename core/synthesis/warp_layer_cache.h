#pragma once
// Warped layers of (source sample, destination sample) pairs, kept for
// reuse. Neighbouring triangles share two vertices and often a
// destination, and a dense sample is reconstructed from many triangles as
// decimation proceeds, so most warps are needed again. Layers are kept in
// half floats (10 bytes a pixel: the capture's own colour precision), least
// recently used first out once the memory budget is reached. The cache
// changes speed only, never a result.

#include "core/synthesis/warp.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <unordered_map>
#include <unordered_set>

namespace triwalk {

// A row of a cached layer in floats, one array per channel (so that a
// blend can read four pixels at a time: core/synthesis/blended_row_error.h),
// also read through the same per-pixel view as WarpLayer. Converting a row
// at a time lets the conversion use the processor's half instructions
// (core/image/half_float.h).
struct DecodedLayerRow {
  std::vector<float> red, green, blue;  // linear
  std::vector<float> distance;          // NaN where not covered
  std::vector<float> reliability;       // empty: 1 everywhere

  bool coveredAt(size_t pixel) const { return !std::isnan(distance[pixel]); }
  float distanceAt(size_t pixel) const { return distance[pixel]; }
  glm::vec3 colorAt(size_t pixel) const { return {red[pixel], green[pixel], blue[pixel]}; }
  float reliabilityAt(size_t pixel) const { return reliability.empty() ? 1.0f : reliability[pixel]; }
};

// A warped layer in half floats: linear r, g, b and the distance (NaN
// where the source put nothing, +inf for sky), and the reliability when
// the layer has one; each a plane of its own, read a row at a time. The
// planes are one block of the process's huge-page blocks
// (core/support/huge_page_blocks.h): a decimation keeps gigabytes of
// layers, and on a fresh machine the kernel's page faults for them were
// a fifth of its CPU.
class CompactLayer {
public:
  explicit CompactLayer(const WarpLayer& layer);
  ~CompactLayer();
  CompactLayer(const CompactLayer&) = delete;
  CompactLayer& operator=(const CompactLayer&) = delete;

  // Pixels [first, first + count) into row (the whole layer: first 0,
  // count pixelCount()).
  void decodeRow(size_t first, size_t count, DecodedLayerRow& row) const;

  size_t pixelCount() const { return pixelCount_; }
  size_t bytes() const { return planeCount() * pixelCount_ * sizeof(uint16_t); }

private:
  size_t planeCount() const { return hasReliability_ ? 5 : 4; }
  std::span<const uint16_t> plane(size_t index) const { return {halves_ + index * pixelCount_, pixelCount_}; }

  size_t pixelCount_;
  bool hasReliability_;
  uint16_t* halves_;  // half floats' bits: the planes red, green, blue, distance, then the reliability if any
};

class WarpLayerCache {
public:
  explicit WarpLayerCache(size_t budgetBytes) : budgetBytes_(budgetBytes) {}

  // The layer of source warped to destination; make() computes it on a
  // miss (outside the lock, so misses run in parallel).
  std::shared_ptr<const CompactLayer> get(int source, int destination, const std::function<WarpLayer()>& make);

  uint64_t hits() const { return hits_; }
  uint64_t misses() const { return misses_; }
  // Misses of layers the cache had held and dropped for the budget: what
  // a larger budget would have saved.
  uint64_t missesAfterEviction() const { return missesAfterEviction_; }
  size_t bytes() const;
  size_t budgetBytes() const;
  // Evicts least recently used layers down to a new budget if it is lower.
  void setBudgetBytes(size_t budgetBytes);
  // Watches the memory the machine has left (availableBytes, e.g.
  // availableMemoryBytes), every kMissesBetweenChecks misses: when it
  // falls below reserveBytes (another process took memory since the
  // budget was set), the budget drops by the shortfall, never below
  // floorBytes, and the dropped layers are handed back to the kernel. The
  // budget never rises again. A long decimation holds most of the
  // machine's memory in layers, so without this it would be the process
  // the kernel kills when another one needs memory.
  void watchMemory(std::function<std::optional<size_t>()> availableBytes, size_t reserveBytes, size_t floorBytes);
  // How many times the watch lowered the budget.
  uint64_t budgetCuts() const;

  static constexpr uint64_t kMissesBetweenChecks = 64;

private:
  using Key = uint64_t;
  using Entry = std::pair<Key, std::shared_ptr<const CompactLayer>>;

  void evictOverBudget();  // with the lock held
  void checkMemory();      // without it

  struct MemoryWatch {
    std::function<std::optional<size_t>()> availableBytes;  // empty: no watch
    size_t reserveBytes = 0, floorBytes = 0;
  };

  size_t budgetBytes_;
  size_t bytes_ = 0;
  std::list<Entry> recency_;  // most recent first
  std::unordered_map<Key, std::list<Entry>::iterator> index_;
  mutable std::mutex mutex_;
  std::unordered_set<Key> evicted_;  // keys dropped for the budget, kept to count their misses
  uint64_t hits_ = 0, misses_ = 0, missesAfterEviction_ = 0;
  MemoryWatch watch_;
  uint64_t budgetCuts_ = 0;
};

// MemAvailable from /proc/meminfo (the kernel's estimate of what can be
// allocated without swapping), or nothing where there is none.
std::optional<size_t> availableMemoryBytes();

// A budget for the cache from the memory left once the views are loaded:
// three quarters of what the kernel reports available, at most 60% of the
// machine's memory, at least 1 GiB. A denser capture needs more layers
// again later than a fixed third of the memory held (docs/history/BENCHMARKS-2026-11.md,
// "the warped-layer cache sized by the memory left"); a layer never needed
// again costs memory only.
size_t automaticLayerCacheBytes();

// The cache of a long decimation: the budget automaticLayerCacheBytes()
// gives, watched (WarpLayerCache::watchMemory) so that the machine keeps
// a sixteenth of its memory (at least 256 MiB) available, the budget
// never dropping below 256 MiB.
void budgetByMachineMemory(WarpLayerCache& cache);

}  // namespace triwalk
