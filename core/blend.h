#pragma once
// Blend of warped layers, the paper's Eq. 1-2 made relative: per pixel,
// z_front is the nearest distance over layers; the layers whose distance
// lies within epsilon * z_front of it are averaged with weights
// w_k = 1 / max(dist(D, S_k), r_min). Pixels no layer covers are holes.
// Sky (+inf) blends with sky.

#include "core/warp.h"

#include <span>

namespace triwalk {

struct BlendOptions {
  float epsilon = 0.05f;               // relative depth interval around z_front
  float minimumWeightDistance = 0.1f;  // r_min, metres
};

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
BlendedPixel blendPixel(std::span<const WarpLayer* const> layers, std::span<const float> weights, size_t pixel,
                        const BlendOptions& options);

// w_k for each source position, seen from the destination.
std::vector<float> blendWeights(glm::vec3 destination, std::span<const glm::vec3> sources, const BlendOptions& options);

BlendedView blendLayers(std::span<const WarpLayer* const> layers, std::span<const float> weights, const BlendOptions& options);

}  // namespace triwalk
