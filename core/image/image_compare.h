#pragma once
// Comparing rendered frames: PSNR, SSIM and per-pixel differences, for the
// CPU-vs-GPU check, golden frames, `render --compare` and `render --truth`.

#include "core/image/image.h"

namespace triwalk {

// Peak signal-to-noise ratio over all channels, in dB (+inf if equal).
double psnr(const Rgb8Image& a, const Rgb8Image& b);
// Structural similarity (Wang, Bovik, Sheikh and Simoncelli 2004) of the
// images' luma (Rec. 601 weights of the display values): 11 x 11 Gaussian
// windows of standard deviation 1.5 pixels, C1 = (0.01 x 255)^2,
// C2 = (0.03 x 255)^2, the mean over every pixel, windows clamped at the
// image's edges. 1 for equal images.
double ssim(const Rgb8Image& a, const Rgb8Image& b);
// Share of pixels whose largest channel difference exceeds tolerance (0..255).
double differingPixelFraction(const Rgb8Image& a, const Rgb8Image& b, int tolerance);
// Per-pixel RMS channel difference in [0, 1], for heatmaps.
ScalarImage differenceImage(const Rgb8Image& a, const Rgb8Image& b);

}  // namespace triwalk
