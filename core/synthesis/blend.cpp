#include "core/synthesis/blend.h"

#include "core/support/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

namespace triwalk {

std::vector<float> blendWeights(glm::vec3 destination, std::span<const glm::vec3> sources, const BlendOptions& options) {
  std::vector<float> weights;
  for (glm::vec3 source : sources) {
    weights.push_back(1.0f / std::max(glm::length(source - destination), options.minimumWeightDistance));
  }
  return weights;
}

BlendedPixel blendPixel(std::span<const WarpLayer* const> layers, std::span<const float> weights, size_t pixel,
                        const BlendOptions& options) {
  return blendPixelOf(layers, weights, pixel, options);
}

BlendedView blendLayers(std::span<const WarpLayer* const> layers, std::span<const float> weights, const BlendOptions& options) {
  TRIWALK_CHECK(!layers.empty() && layers.size() == weights.size() && layers.size() <= 8, "one weight per layer, at most 8");
  const int width = layers[0]->color.width, height = layers[0]->color.height;
  const size_t pixels = size_t(width) * size_t(height);
  BlendedView view{ColorImage(width, height), ScalarImage(width, height, std::numeric_limits<float>::infinity()),
                   std::vector<uint8_t>(pixels, 0), std::vector<uint8_t>(pixels, 0)};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, pixels, 8192), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const BlendedPixel pixel = blendPixel(layers, weights, i, options);
      view.hole[i] = pixel.hole;
      if (pixel.hole) continue;
      view.color.pixels[i] = pixel.color;
      view.distance.pixels[i] = pixel.distance;
      view.contributors[i] = pixel.contributors;
    }
  });
  return view;
}

}  // namespace triwalk
