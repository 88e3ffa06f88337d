#pragma once
// Warped layers of (source sample, destination sample) pairs. Neighbouring
// triangles share two vertices and often a destination, so during
// decimation most of a triangle error's warps were already done for
// another triangle. Least recently used layers go first once the memory
// budget is reached. The cache changes speed only, never a result.

#include "core/warp.h"

#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>

namespace triwalk {

class WarpLayerCache {
public:
  explicit WarpLayerCache(size_t budgetBytes) : budgetBytes_(budgetBytes) {}

  // The layer of source warped to destination; make() computes it on a
  // miss (outside the lock, so misses run in parallel).
  std::shared_ptr<const WarpLayer> get(int source, int destination, const std::function<WarpLayer()>& make);

  uint64_t hits() const { return hits_; }
  uint64_t misses() const { return misses_; }
  size_t bytes() const;

private:
  using Key = uint64_t;
  using Entry = std::pair<Key, std::shared_ptr<const WarpLayer>>;

  size_t budgetBytes_;
  size_t bytes_ = 0;
  std::list<Entry> recency_;  // most recent first
  std::unordered_map<Key, std::list<Entry>::iterator> index_;
  mutable std::mutex mutex_;
  uint64_t hits_ = 0, misses_ = 0;
};

size_t layerBytes(const WarpLayer& layer);

}  // namespace triwalk
