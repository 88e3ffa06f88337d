#include "core/import/depth_decoding.h"

#include "core/geometry/projection.h"
#include "core/io/exr_io.h"
#include "core/io/png_io.h"
#include "core/support/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace triwalk {

DepthKind parseDepthKind(const std::string& text, const std::string& option) {
  if (text == "euclidean") return DepthKind::Euclidean;
  if (text == "cube-z") return DepthKind::CubeZ;
  if (text == "horizontal") return DepthKind::Horizontal;
  throw InputError(option, "unknown depth kind '" + text + "' (euclidean, cube-z or horizontal)");
}

const char* depthKindName(DepthKind kind) {
  switch (kind) {
    case DepthKind::Euclidean: return "euclidean";
    case DepthKind::CubeZ: return "cube-z";
    case DepthKind::Horizontal: return "horizontal";
  }
  return "euclidean";
}

DecodedDepth decodeDepthFile(const DepthFile& file) {
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  DecodedDepth decoded;
  const float scale = float(1.0 / file.unitsPerMetre);
  if (file.path.extension() == ".exr") {
    decoded.metres = readDepthExr(file.path);
    for (float& value : decoded.metres.pixels) {
      const bool invalid = value == 0.0f || std::isinf(value);
      decoded.invalidPixels += invalid;
      value = invalid ? kInfinity : value * scale;
    }
  } else {
    const Gray16Image stored = readPng16(file.path);
    decoded.metres = ScalarImage(stored.width, stored.height);
    for (size_t i = 0; i < stored.pixelCount(); ++i) {
      const bool invalid = stored.pixels[i] == 0;
      decoded.invalidPixels += invalid;
      decoded.metres.pixels[i] = invalid ? kInfinity : float(stored.pixels[i]) * scale;
    }
  }
  return decoded;
}

float depthOfKind(float distance, glm::vec3 cameraRay, DepthKind kind) {
  switch (kind) {
    case DepthKind::Euclidean: return distance;
    case DepthKind::CubeZ: return distance * std::max({std::abs(cameraRay.x), std::abs(cameraRay.y), std::abs(cameraRay.z)});
    case DepthKind::Horizontal: return distance * std::hypot(cameraRay.x, cameraRay.y);
  }
  return distance;
}

void convertToDistance(ScalarImage& depth, DepthKind kind) {
  if (kind == DepthKind::Euclidean) return;
  const EquirectProjection projection{depth.width, depth.height, 0.0f};
  for (int v = 0; v < depth.height; ++v) {
    for (int u = 0; u < depth.width; ++u) {
      // Pixel centres never reach the poles, so the factor stays positive.
      depth.at(u, v) /= depthOfKind(1.0f, projection.pixelDirection(u, v), kind);
    }
  }
}

}  // namespace triwalk
