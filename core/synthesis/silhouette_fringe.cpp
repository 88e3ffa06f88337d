#include "core/synthesis/silhouette_fringe.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace triwalk {

namespace {

bool acrossDiscontinuity(float a, float b) {
  const bool infiniteA = std::isinf(a), infiniteB = std::isinf(b);
  if (infiniteA || infiniteB) return infiniteA != infiniteB;
  return std::max(a, b) > kFringeDepthRatio * std::min(a, b);
}

}  // namespace

std::vector<uint8_t> silhouetteFringe(const ScalarImage& distance) {
  const int width = distance.width, height = distance.height;
  std::vector<uint8_t> fringe(size_t(width) * size_t(height), 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      for (int x = 0; x < width; ++x) {
        const float here = distance.at(x, y);
        bool mixed = false;
        for (int dy = -1; dy <= 1 && !mixed; ++dy) {
          const int ny = y + dy;
          if (ny < 0 || ny >= height) continue;
          for (int dx = -1; dx <= 1 && !mixed; ++dx) {
            const int nx = (x + dx + width) % width;
            mixed = acrossDiscontinuity(here, distance.at(nx, ny));
          }
        }
        fringe[size_t(y) * size_t(width) + size_t(x)] = mixed;
      }
    }
  });
  return fringe;
}

}  // namespace triwalk
