#pragma once
// The paper's reconstruction error (Eq. 3-5) between a reconstruction and
// the ground truth, on display colors (sRGB-encoded, clamped to [0, 1]):
//   R = RMS over pixels and channels of the color difference (0..1)
//   B = percentage of pixels whose largest channel difference exceeds delta / 255
//   E = alpha R + beta B        (alpha 10, beta 0.1, delta 15 as in the paper)
// Holes count as black for R and always as bad for B. Pixels are weighted
// by solid angle (cos latitude) for panoramas by default, or uniformly as
// in the paper.

#include "core/image/image.h"

#include <string>
#include <vector>

namespace triwalk {

enum class PixelWeighting { SolidAngle, Uniform };

PixelWeighting parsePixelWeighting(const std::string& name);  // "solid-angle" | "uniform"
const char* pixelWeightingName(PixelWeighting weighting);

struct ErrorOptions {
  double alpha = 10.0;
  double beta = 0.1;
  double delta = 15.0;  // on the 0..255 scale
  PixelWeighting weighting = PixelWeighting::SolidAngle;
};

struct ReconstructionError {
  double rms = 0.0;         // R
  double badPercent = 0.0;  // B, in percent
  double total = 0.0;       // E
};

// The error of a W x H image computed pixel by pixel: rows may be filled
// in parallel (each row by one thread); the totals are summed in row
// order, so the result does not depend on the thread count.
class ErrorAccumulator {
public:
  ErrorAccumulator(int width, int height, const ErrorOptions& options);
  // A pixel in display colors; returns its RMS channel difference (1 for holes).
  float add(int y, glm::vec3 reconstruction, bool hole, glm::vec3 truth);
  ReconstructionError result() const;

private:
  int width_;
  ErrorOptions options_;
  double badThreshold_;
  std::vector<double> rowSquared_, rowBad_, rowWeight_;
};

// Display colors of a linear image.
ColorImage toDisplayColors(const ColorImage& linear);

// reconstruction and truth in display colors, same size; hole may be empty
// (no holes). Solid-angle weighting treats the images as equirectangular.
// If perPixel is given, it receives each pixel's RMS channel difference
// (1 for holes), for heatmaps.
ReconstructionError reconstructionError(const ColorImage& reconstruction, const std::vector<uint8_t>& hole,
                                        const ColorImage& truth, const ErrorOptions& options,
                                        ScalarImage* perPixel = nullptr);

}  // namespace triwalk
