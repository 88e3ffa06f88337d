#include "core/image/panorama_resample.h"

#include "core/support/errors.h"

#include <algorithm>

namespace triwalk {

Panorama downsamplePanorama(const Panorama& panorama, int factor) {
  TRIWALK_CHECK(factor >= 1 && panorama.width() % factor == 0 && panorama.height() % factor == 0,
                "downsampling factor must divide the panorama size");
  if (factor == 1) return panorama;
  const int width = panorama.width() / factor, height = panorama.height() / factor;
  Panorama result{ColorImage(width, height), ScalarImage(width, height)};
  std::vector<float> block(size_t(factor) * size_t(factor));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      glm::vec3 sum(0.0f);
      size_t n = 0;
      for (int dy = 0; dy < factor; ++dy) {
        for (int dx = 0; dx < factor; ++dx) {
          sum += panorama.color.at(x * factor + dx, y * factor + dy);
          block[n++] = panorama.distance.at(x * factor + dx, y * factor + dy);
        }
      }
      std::nth_element(block.begin(), block.begin() + ptrdiff_t(n / 2), block.end());
      result.color.at(x, y) = sum / float(n);
      result.distance.at(x, y) = block[n / 2];
    }
  }
  return result;
}

}  // namespace triwalk
