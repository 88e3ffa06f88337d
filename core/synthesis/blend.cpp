#include "core/synthesis/blend.h"

#include "core/support/errors.h"

#include <cmath>
#include <limits>

namespace triwalk {

BlendWeights parseBlendWeights(const std::string& name) {
  if (name == "reliability") return BlendWeights::Reliability;
  if (name == "distance") return BlendWeights::Distance;
  throw InputError("blend_weights", "unknown blend weights '" + name + "' (use reliability or distance)");
}

const char* blendWeightsName(BlendWeights weights) {
  return weights == BlendWeights::Reliability ? "reliability" : "distance";
}

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
  return blendLayersOf(layers, weights, layers[0]->color.width, layers[0]->color.height, options);
}

}  // namespace triwalk
