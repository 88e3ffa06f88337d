#pragma once
// Comparing rendered frames: PSNR and per-pixel differences, for the
// CPU-vs-GPU check, golden frames and `render --compare`.

#include "core/image/image.h"

namespace triwalk {

// Peak signal-to-noise ratio over all channels, in dB (+inf if equal).
double psnr(const Rgb8Image& a, const Rgb8Image& b);
// Share of pixels whose largest channel difference exceeds tolerance (0..255).
double differingPixelFraction(const Rgb8Image& a, const Rgb8Image& b, int tolerance);
// Per-pixel RMS channel difference in [0, 1], for heatmaps.
ScalarImage differenceImage(const Rgb8Image& a, const Rgb8Image& b);

}  // namespace triwalk
