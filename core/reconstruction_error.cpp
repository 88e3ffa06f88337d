#include "core/reconstruction_error.h"

#include "core/color.h"
#include "core/errors.h"
#include "core/projection.h"

#include <cmath>

namespace triwalk {

PixelWeighting parsePixelWeighting(const std::string& name) {
  if (name == "solid-angle") return PixelWeighting::SolidAngle;
  if (name == "uniform") return PixelWeighting::Uniform;
  throw InputError("--pixel-weighting", "unknown weighting '" + name + "' (use solid-angle or uniform)");
}

const char* pixelWeightingName(PixelWeighting weighting) {
  return weighting == PixelWeighting::SolidAngle ? "solid-angle" : "uniform";
}

ColorImage toDisplayColors(const ColorImage& linear) {
  ColorImage display(linear.width, linear.height);
  for (size_t i = 0; i < linear.pixelCount(); ++i) display.pixels[i] = displayColor(linear.pixels[i]);
  return display;
}

ReconstructionError reconstructionError(const ColorImage& reconstruction, const std::vector<uint8_t>& hole,
                                        const ColorImage& truth, const ErrorOptions& options, ScalarImage* perPixel) {
  TRIWALK_CHECK(reconstruction.width == truth.width && reconstruction.height == truth.height, "image sizes differ");
  TRIWALK_CHECK(hole.empty() || hole.size() == truth.pixelCount(), "hole mask size differs");
  const int width = truth.width, height = truth.height;
  const EquirectProjection projection{width, height, 0.0f};
  const double badThreshold = options.delta / 255.0;
  if (perPixel) *perPixel = ScalarImage(width, height);

  double weightSum = 0.0, squaredSum = 0.0, badSum = 0.0;
  for (int y = 0; y < height; ++y) {
    const double rowWeight = options.weighting == PixelWeighting::SolidAngle ? projection.rowSolidAngleWeight(y) : 1.0;
    double rowSquared = 0.0, rowBad = 0.0;
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      const bool isHole = !hole.empty() && hole[i];
      const glm::vec3 reconstructed = isHole ? glm::vec3(0.0f) : reconstruction.pixels[i];
      const glm::dvec3 difference = glm::abs(glm::dvec3(reconstructed) - glm::dvec3(truth.pixels[i]));
      const double squared = glm::dot(difference, difference);
      rowSquared += squared;
      rowBad += (isHole || std::max({difference.r, difference.g, difference.b}) > badThreshold) ? 1.0 : 0.0;
      if (perPixel) perPixel->pixels[i] = isHole ? 1.0f : float(std::sqrt(squared / 3.0));
    }
    weightSum += rowWeight * width;
    squaredSum += rowWeight * rowSquared;
    badSum += rowWeight * rowBad;
  }
  ReconstructionError error;
  error.rms = std::sqrt(squaredSum / (3.0 * weightSum));
  error.badPercent = 100.0 * badSum / weightSum;
  error.total = options.alpha * error.rms + options.beta * error.badPercent;
  return error;
}

}  // namespace triwalk
