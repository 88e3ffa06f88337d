#include "core/synthesis/silhouette_fringe.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace triwalk {

namespace {

// Whether `here` lies behind `neighbour` across a discontinuity: the sky
// beside a surface, or a surface farther by more than kFringeDepthRatio.
bool behind(float here, float neighbour) {
  if (std::isinf(neighbour)) return false;
  return std::isinf(here) || here > kFringeDepthRatio * neighbour;
}

}  // namespace

std::vector<uint8_t> silhouetteFringe(const ScalarImage& distance) {
  const int width = distance.width, height = distance.height;
  std::vector<uint8_t> fringe(size_t(width) * size_t(height), 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      for (int x = 0; x < width; ++x) {
        const float here = distance.at(x, y);
        bool flagged = false;
        for (int dy = -1; dy <= 1 && !flagged; ++dy) {
          const int ny = y + dy;
          if (ny < 0 || ny >= height) continue;
          for (int dx = -1; dx <= 1 && !flagged; ++dx) {
            const int nx = (x + dx + width) % width;
            flagged = behind(here, distance.at(nx, ny));
          }
        }
        fringe[size_t(y) * size_t(width) + size_t(x)] = flagged;
      }
    }
  });
  return fringe;
}

}  // namespace triwalk
