#include "core/image/image_compare.h"

#include "core/support/errors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

namespace triwalk {

namespace {

std::vector<double> luma(const Rgb8Image& image) {
  std::vector<double> values(image.pixelCount());
  for (size_t i = 0; i < values.size(); ++i) {
    const glm::u8vec3 p = image.pixels[i];
    values[i] = 0.299 * double(p.r) + 0.587 * double(p.g) + 0.114 * double(p.b);
  }
  return values;
}

// The Gaussian-weighted local mean of every pixel, separably, the window
// clamped at the edges (the edge pixels repeated).
std::vector<double> gaussianMean(const std::vector<double>& values, int width, int height) {
  constexpr int kRadius = 5;
  constexpr double kSigma = 1.5;
  std::array<double, 2 * kRadius + 1> taps{};
  double total = 0.0;
  for (int k = -kRadius; k <= kRadius; ++k) total += taps[size_t(k + kRadius)] = std::exp(-0.5 * k * k / (kSigma * kSigma));
  for (double& tap : taps) tap /= total;
  auto clampTo = [](int i, int size) { return std::clamp(i, 0, size - 1); };
  std::vector<double> rows(values.size()), result(values.size());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double sum = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) sum += taps[size_t(k + kRadius)] * values[size_t(y) * size_t(width) + size_t(clampTo(x + k, width))];
      rows[size_t(y) * size_t(width) + size_t(x)] = sum;
    }
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double sum = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) sum += taps[size_t(k + kRadius)] * rows[size_t(clampTo(y + k, height)) * size_t(width) + size_t(x)];
      result[size_t(y) * size_t(width) + size_t(x)] = sum;
    }
  }
  return result;
}

}  // namespace

double psnr(const Rgb8Image& a, const Rgb8Image& b) {
  TRIWALK_CHECK(a.width == b.width && a.height == b.height, "images differ in size");
  double squared = 0.0;
  for (size_t i = 0; i < a.pixelCount(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double d = (double(a.pixels[i][c]) - double(b.pixels[i][c])) / 255.0;
      squared += d * d;
    }
  }
  const double mse = squared / (3.0 * double(a.pixelCount()));
  return mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(1.0 / mse);
}

double ssim(const Rgb8Image& a, const Rgb8Image& b) {
  TRIWALK_CHECK(a.width == b.width && a.height == b.height, "images differ in size");
  const std::vector<double> x = luma(a), y = luma(b);
  std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
  for (size_t i = 0; i < x.size(); ++i) xx[i] = x[i] * x[i], yy[i] = y[i] * y[i], xy[i] = x[i] * y[i];
  const std::vector<double> meanX = gaussianMean(x, a.width, a.height), meanY = gaussianMean(y, a.width, a.height);
  const std::vector<double> meanXX = gaussianMean(xx, a.width, a.height), meanYY = gaussianMean(yy, a.width, a.height);
  const std::vector<double> meanXY = gaussianMean(xy, a.width, a.height);
  constexpr double c1 = (0.01 * 255.0) * (0.01 * 255.0), c2 = (0.03 * 255.0) * (0.03 * 255.0);
  double sum = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double mx = meanX[i], my = meanY[i];
    const double varianceX = meanXX[i] - mx * mx, varianceY = meanYY[i] - my * my, covariance = meanXY[i] - mx * my;
    sum += (2.0 * mx * my + c1) * (2.0 * covariance + c2) / ((mx * mx + my * my + c1) * (varianceX + varianceY + c2));
  }
  return sum / double(x.size());
}

double differingPixelFraction(const Rgb8Image& a, const Rgb8Image& b, int tolerance) {
  TRIWALK_CHECK(a.width == b.width && a.height == b.height, "images differ in size");
  size_t differing = 0;
  for (size_t i = 0; i < a.pixelCount(); ++i) {
    int largest = 0;
    for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(int(a.pixels[i][c]) - int(b.pixels[i][c])));
    differing += largest > tolerance;
  }
  return double(differing) / double(a.pixelCount());
}

ScalarImage differenceImage(const Rgb8Image& a, const Rgb8Image& b) {
  TRIWALK_CHECK(a.width == b.width && a.height == b.height, "images differ in size");
  ScalarImage difference(a.width, a.height);
  for (size_t i = 0; i < a.pixelCount(); ++i) {
    double squared = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = (double(a.pixels[i][c]) - double(b.pixels[i][c])) / 255.0;
      squared += d * d;
    }
    difference.pixels[i] = float(std::sqrt(squared / 3.0));
  }
  return difference;
}

}  // namespace triwalk
