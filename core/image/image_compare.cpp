#include "core/image/image_compare.h"

#include "core/support/errors.h"

#include <cmath>
#include <cstdlib>
#include <limits>

namespace triwalk {

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
