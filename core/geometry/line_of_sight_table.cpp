#include "core/geometry/line_of_sight_table.h"

namespace triwalk {

LineOfSightTable::LineOfSightTable(std::span<const glm::dvec2> positions, const WalkableRegion* region) {
  if (!region || region->empty() || region->convex()) return;
  positions_.assign(positions.begin(), positions.end());
  region_ = region;
  const size_t pairs = positions_.size() * positions_.size();
  known_ = std::make_unique<std::atomic<int8_t>[]>(pairs);
  for (size_t k = 0; k < pairs; ++k) known_[k].store(-1, std::memory_order_relaxed);
}

bool LineOfSightTable::sees(int a, int b) const {
  if (!known_) return true;
  std::atomic<int8_t>& known = known_[size_t(a) * positions_.size() + size_t(b)];
  int8_t answer = known.load(std::memory_order_relaxed);
  if (answer < 0) {
    answer = region_->lineOfSight(positions_[size_t(a)], positions_[size_t(b)]) ? 1 : 0;
    known.store(answer, std::memory_order_relaxed);
  }
  return answer != 0;
}

}  // namespace triwalk
