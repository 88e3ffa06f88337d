#include "core/synthesis/reconstruction_error.h"

#include "core/geometry/projection.h"
#include "core/image/color.h"
#include "core/support/errors.h"

#include <cmath>

namespace triwalk {

PixelWeighting parsePixelWeighting(const std::string& name) {
  if (name == "solid-angle") return PixelWeighting::SolidAngle;
  if (name == "uniform") return PixelWeighting::Uniform;
  throw InputError("pixel_weighting", "unknown weighting '" + name + "' (use solid-angle or uniform)");
}

const char* pixelWeightingName(PixelWeighting weighting) {
  return weighting == PixelWeighting::SolidAngle ? "solid-angle" : "uniform";
}

ColorImage toDisplayColors(const ColorImage& linear) {
  ColorImage display(linear.width, linear.height);
  for (size_t i = 0; i < linear.pixelCount(); ++i) display.pixels[i] = displayColorFast(linear.pixels[i]);
  return display;
}

ErrorAccumulator::ErrorAccumulator(int width, int height, const ErrorOptions& options, int stride)
    : width_(width), stride_(stride), options_(options), badThreshold_(options.delta / 255.0), rowSquared_(size_t(height), 0.0),
      rowBad_(size_t(height), 0.0), rowWeight_(size_t(height), 1.0) {
  TRIWALK_CHECK(stride >= 1 && width % stride == 0 && height % stride == 0, "an error's stride must divide the image");
  if (options.weighting == PixelWeighting::SolidAngle) {
    const EquirectProjection projection{width, height, 0.0f};
    for (int y = 0; y < height; ++y) rowWeight_[size_t(y)] = projection.rowSolidAngleWeight(y);
  }
}

void ErrorAccumulator::addRow(int y, std::span<const float> squared, std::span<const float> largest,
                              std::span<const uint8_t> hole) {
  TRIWALK_CHECK(largest.size() == squared.size() && hole.size() == squared.size(), "one difference per pixel");
  double squaredSum = rowSquared_[size_t(y)], badCount = rowBad_[size_t(y)];
  for (size_t i = 0; i < squared.size(); ++i) {
    squaredSum += double(squared[i]);
    badCount += isBad(largest[i], hole[i] != 0) ? 1.0 : 0.0;
  }
  rowSquared_[size_t(y)] = squaredSum;
  rowBad_[size_t(y)] = badCount;
}

ReconstructionError ErrorAccumulator::result() const {
  double weightSum = 0.0, squaredSum = 0.0, badSum = 0.0;
  for (size_t y = 0; y < rowWeight_.size(); y += size_t(stride_)) {
    weightSum += rowWeight_[y] * (width_ / stride_);
    squaredSum += rowWeight_[y] * rowSquared_[y];
    badSum += rowWeight_[y] * rowBad_[y];
  }
  ReconstructionError error;
  error.rms = std::sqrt(squaredSum / (3.0 * weightSum));
  error.badPercent = 100.0 * badSum / weightSum;
  error.total = options_.alpha * error.rms + options_.beta * error.badPercent;
  return error;
}

ReconstructionError reconstructionError(const ColorImage& reconstruction, const std::vector<uint8_t>& hole,
                                        const ColorImage& truth, const ErrorOptions& options, ScalarImage* perPixel) {
  TRIWALK_CHECK(reconstruction.width == truth.width && reconstruction.height == truth.height, "image sizes differ");
  TRIWALK_CHECK(hole.empty() || hole.size() == truth.pixelCount(), "hole mask size differs");
  const int width = truth.width, height = truth.height;
  if (perPixel) *perPixel = ScalarImage(width, height);
  ErrorAccumulator accumulator(width, height, options);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      const float pixelError = accumulator.add(y, reconstruction.pixels[i], !hole.empty() && hole[i], truth.pixels[i]);
      if (perPixel) perPixel->pixels[i] = pixelError;
    }
  }
  return accumulator.result();
}

}  // namespace triwalk
