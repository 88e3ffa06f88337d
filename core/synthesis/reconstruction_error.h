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
#include "core/support/option_range.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
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

// E = alpha R + beta B stays finite and ordered for weights up to a
// million (R <= 1, B <= 100); the tolerance is on the 0..255 scale.
inline constexpr OptionRange kErrorWeightRange{0.0f, 1e6f};
inline constexpr OptionRange kBadPixelToleranceRange{0.0f, 255.0f};

struct ReconstructionError {
  double rms = 0.0;         // R
  double badPercent = 0.0;  // B, in percent
  double total = 0.0;       // E
};

// The error of a W x H image computed pixel by pixel: rows may be filled
// in parallel (each row by one thread); the totals are summed in row
// order, so the result does not depend on the thread count. With a
// stride, the error of its lattice (every stride-th row and column, as
// DestinationCamera::panoramaLattice warps): only those rows are added
// to, W / stride pixels each, and weighted by their own latitudes.
class ErrorAccumulator {
public:
  ErrorAccumulator(int width, int height, const ErrorOptions& options, int stride = 1);
  // A pixel in display colors; returns its RMS channel difference (1 for
  // holes). Inline: every pixel of every reconstruction comes through here.
  float add(int y, glm::vec3 reconstruction, bool hole, glm::vec3 truth) {
    // Per pixel in float (display values in [0, 1]); rows sum in double.
    // std::abs clears the sign bit; glm::abs compares and branches, and the
    // differences' signs are random, so it mispredicted: a quarter of a
    // cached-layer error's time (docs/history/BENCHMARKS-2026-11.md). The same values.
    const glm::vec3 signedDifference = (hole ? glm::vec3(0.0f) : reconstruction) - truth;
    const glm::vec3 difference(std::abs(signedDifference.r), std::abs(signedDifference.g),
                               std::abs(signedDifference.b));
    const float squared = glm::dot(difference, difference);
    const float largest = std::max(difference.r, std::max(difference.g, difference.b));
    rowSquared_[size_t(y)] += double(squared);
    rowBad_[size_t(y)] += isBad(largest, hole) ? 1.0 : 0.0;
    return hole ? 1.0f : std::sqrt(squared / 3.0f);
  }
  // The pixels of row y whose differences were computed elsewhere, as add
  // computes them (four at a time: core/synthesis/blended_row_error.h):
  // each one's squared channel difference, largest channel difference and
  // hole flag. The same sums as adding them one by one.
  void addRow(int y, std::span<const float> squared, std::span<const float> largest, std::span<const uint8_t> hole);
  ReconstructionError result() const;

private:
  bool isBad(float largest, bool hole) const { return hole || double(largest) > badThreshold_; }

  int width_;
  int stride_;
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
