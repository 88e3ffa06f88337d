#pragma once
// Blend of warped layers, the paper's Eq. 1-2 made relative: per pixel,
// z_front is the nearest distance over layers; the layers whose distance
// lies within epsilon * z_front of it are averaged with weights
// w_k = 1 / max(dist(D, S_k), r_min), times each layer's reliability at the
// pixel (core/synthesis/warp_reliability.h) unless the paper's weights
// alone are asked for. Pixels no layer covers are holes. Sky (+inf) blends
// with sky.

#include "core/support/option_range.h"
#include "core/synthesis/warp.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

namespace triwalk {

// What the blend weighs a layer by, within the epsilon interval.
enum class BlendWeights {
  Reliability,  // inverse distance times the layer's reliability at the pixel
  Distance,     // inverse distance alone, the paper's
};

// Parses "reliability", "distance"; throws InputError naming --blend-weights.
BlendWeights parseBlendWeights(const std::string& name);
const char* blendWeightsName(BlendWeights weights);

struct BlendOptions {
  float epsilon = 0.05f;               // relative depth interval around z_front
  float minimumWeightDistance = 0.1f;  // r_min, metres
  BlendWeights weights = BlendWeights::Reliability;

  bool operator==(const BlendOptions&) const = default;
};

// The interval must be wider than nothing, or the nearest layer falls
// outside its own interval and a pixel has no weight (a NaN colour).
inline constexpr OptionRange kEpsilonRange{1e-4f, 10.0f};
// r_min in metres: below a millimetre a reference at the destination
// would weigh more than a float holds beside the others; beyond 10 km
// every weight is the same 1 / r_min in any scene triwalk reads.
inline constexpr OptionRange kMinimumWeightDistanceRange{1e-3f, 1e4f};

struct BlendedView {
  ColorImage color;                  // linear; black in holes
  ScalarImage distance;              // z_front, metres; +inf for sky and holes
  std::vector<uint8_t> hole;         // 1 where no layer covers the pixel
  std::vector<uint8_t> contributors; // bit k set where layer k was blended
};

// One pixel of the blend; hole when no layer covers it.
struct BlendedPixel {
  glm::vec3 color{0.0f};  // linear
  float distance = 0.0f;
  uint8_t contributors = 0;
  bool hole = true;
};

// The blend of one pixel over layers of any storage: each layer's
// coveredAt(pixel), distanceAt(pixel), colorAt(pixel) and
// reliabilityAt(pixel) (WarpLayer here, the warped-layer cache's half-float
// layers for decimation).
template <typename Layer>
BlendedPixel blendPixelOf(std::span<const Layer* const> layers, std::span<const float> weights, size_t pixel,
                          const BlendOptions& options) {
  BlendedPixel result;
  float distances[8];
  float front = std::numeric_limits<float>::infinity();
  for (size_t k = 0; k < layers.size(); ++k) {
    const bool covered = layers[k]->coveredAt(pixel);
    distances[k] = covered ? layers[k]->distanceAt(pixel) : std::numeric_limits<float>::quiet_NaN();
    if (!covered) continue;
    result.hole = false;
    front = std::min(front, distances[k]);
  }
  if (result.hole) return result;
  glm::vec3 sum(0.0f);
  float weightSum = 0.0f;
  for (size_t k = 0; k < layers.size(); ++k) {
    const float d = distances[k];
    if (std::isnan(d)) continue;
    const bool inInterval = std::isinf(front) ? std::isinf(d) : std::abs(d - front) < options.epsilon * front;
    if (!inInterval) continue;
    const float weight =
        options.weights == BlendWeights::Reliability ? weights[k] * layers[k]->reliabilityAt(pixel) : weights[k];
    sum += weight * layers[k]->colorAt(pixel);
    weightSum += weight;
    result.contributors |= uint8_t(1u << k);
  }
  result.color = sum / weightSum;
  result.distance = front;
  return result;
}

// The blended image of layers of any storage (see blendPixelOf).
template <typename Layer>
BlendedView blendLayersOf(std::span<const Layer* const> layers, std::span<const float> weights, int width, int height,
                          const BlendOptions& options) {
  const size_t pixels = size_t(width) * size_t(height);
  BlendedView view{ColorImage(width, height), ScalarImage(width, height, std::numeric_limits<float>::infinity()),
                   std::vector<uint8_t>(pixels, 0), std::vector<uint8_t>(pixels, 0)};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, pixels, 8192), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const BlendedPixel pixel = blendPixelOf(layers, weights, i, options);
      view.hole[i] = pixel.hole;
      if (pixel.hole) continue;
      view.color.pixels[i] = pixel.color;
      view.distance.pixels[i] = pixel.distance;
      view.contributors[i] = pixel.contributors;
    }
  });
  return view;
}

BlendedPixel blendPixel(std::span<const WarpLayer* const> layers, std::span<const float> weights, size_t pixel,
                        const BlendOptions& options);

// w_k for each source position, seen from the destination.
std::vector<float> blendWeights(glm::vec3 destination, std::span<const glm::vec3> sources, const BlendOptions& options);

BlendedView blendLayers(std::span<const WarpLayer* const> layers, std::span<const float> weights, const BlendOptions& options);

}  // namespace triwalk
