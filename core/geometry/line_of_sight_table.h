#pragma once
// Whether two samples see each other across the walkable region (the
// segment between them stays inside it), traced once per pair and then
// remembered: the decimator and the refinement rank the same (reference,
// sample) pairs in every mesh they try, and tracing a line through a
// level's walls each time cost a seventh of a tiled seam step. A region
// without walls keeps no table (everything sees everything). Safe to ask
// from several threads: two that race trace the same answer and store it.

#include "core/geometry/walkable_region.h"

#include <glm/glm.hpp>

#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace triwalk {

class LineOfSightTable {
public:
  // positions: every sample's (x, y) by index; region: kept by the caller
  // for the table's life (none, empty or convex: no table).
  LineOfSightTable(std::span<const glm::dvec2> positions, const WalkableRegion* region);

  bool sees(int a, int b) const;

private:
  std::vector<glm::dvec2> positions_;
  const WalkableRegion* region_ = nullptr;
  // Per (a, b): -1 not traced yet, else whether they see each other.
  std::unique_ptr<std::atomic<int8_t>[]> known_;
};

}  // namespace triwalk
