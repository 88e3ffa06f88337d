#include "core/blend.h"

#include "core/errors.h"

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

BlendedView blendLayers(std::span<const WarpLayer> layers, std::span<const float> weights, const BlendOptions& options) {
  TRIWALK_CHECK(!layers.empty() && layers.size() == weights.size() && layers.size() <= 8, "one weight per layer, at most 8");
  const int width = layers[0].color.width, height = layers[0].color.height;
  const size_t pixels = size_t(width) * size_t(height);
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  BlendedView view{ColorImage(width, height), ScalarImage(width, height, kInfinity), std::vector<uint8_t>(pixels, 0),
                   std::vector<uint8_t>(pixels, 0)};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, pixels, 8192), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      float front = kInfinity;
      bool covered = false;
      for (const WarpLayer& layer : layers) {
        if (!layer.covered[i]) continue;
        covered = true;
        front = std::min(front, layer.distance.pixels[i]);
      }
      if (!covered) {
        view.hole[i] = 1;
        continue;
      }
      glm::vec3 sum(0.0f);
      float weightSum = 0.0f;
      uint8_t contributors = 0;
      for (size_t k = 0; k < layers.size(); ++k) {
        const WarpLayer& layer = layers[k];
        if (!layer.covered[i]) continue;
        const float d = layer.distance.pixels[i];
        const bool inInterval = std::isinf(front) ? std::isinf(d) : std::abs(d - front) < options.epsilon * front;
        if (!inInterval) continue;
        sum += weights[k] * layer.color.pixels[i];
        weightSum += weights[k];
        contributors |= uint8_t(1u << k);
      }
      view.color.pixels[i] = sum / weightSum;
      view.distance.pixels[i] = front;
      view.contributors[i] = contributors;
    }
  });
  return view;
}

}  // namespace triwalk
