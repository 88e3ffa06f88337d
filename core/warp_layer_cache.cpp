#include "core/warp_layer_cache.h"

namespace triwalk {

size_t layerBytes(const WarpLayer& layer) {
  return layer.color.pixelCount() * sizeof(glm::vec3) + layer.distance.pixelCount() * sizeof(float) + layer.covered.size();
}

size_t WarpLayerCache::bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}

std::shared_ptr<const WarpLayer> WarpLayerCache::get(int source, int destination, const std::function<WarpLayer()>& make) {
  const Key key = (uint64_t(uint32_t(source)) << 32) | uint32_t(destination);
  {
    std::lock_guard lock(mutex_);
    const auto found = index_.find(key);
    if (found != index_.end()) {
      recency_.splice(recency_.begin(), recency_, found->second);
      ++hits_;
      return found->second->second;
    }
    ++misses_;
  }
  auto layer = std::make_shared<const WarpLayer>(make());
  std::lock_guard lock(mutex_);
  const auto found = index_.find(key);
  if (found != index_.end()) return found->second->second;  // another thread made it meanwhile
  recency_.emplace_front(key, layer);
  index_[key] = recency_.begin();
  bytes_ += layerBytes(*layer);
  while (bytes_ > budgetBytes_ && recency_.size() > 1) {
    bytes_ -= layerBytes(*recency_.back().second);
    index_.erase(recency_.back().first);
    recency_.pop_back();
  }
  return layer;
}

}  // namespace triwalk
