// Frame comparison measures on images whose answer is known: SSIM of
// constant images has a closed form, an image against itself scores 1,
// and inverting an image's structure makes it negative.

#include "core/image/image_compare.h"

#include <doctest/doctest.h>

#include <cstdint>

namespace triwalk {
namespace {

Rgb8Image constantImage(int width, int height, uint8_t grey) {
  Rgb8Image image(width, height);
  for (glm::u8vec3& pixel : image.pixels) pixel = glm::u8vec3(grey);
  return image;
}

// A checkerboard of 4-pixel squares, lo and hi.
Rgb8Image checkerboard(int width, int height, uint8_t lo, uint8_t hi) {
  Rgb8Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) image.at(x, y) = glm::u8vec3(((x / 4 + y / 4) % 2) != 0 ? hi : lo);
  }
  return image;
}

}  // namespace

TEST_CASE("SSIM: constant images score (2ab + C1) / (a^2 + b^2 + C1), an image against itself 1, inverted structure below 0") {
  constexpr double c1 = 6.5025;  // (0.01 x 255)^2
  const double a = 100.0, b = 140.0;
  CHECK(ssim(constantImage(32, 24, 100), constantImage(32, 24, 140)) ==
        doctest::Approx((2.0 * a * b + c1) / (a * a + b * b + c1)).epsilon(1e-9));
  const Rgb8Image board = checkerboard(40, 30, 60, 200);
  CHECK(ssim(board, board) == doctest::Approx(1.0).epsilon(1e-12));
  // The same means, the structure reversed: the covariance is negative.
  CHECK(ssim(board, checkerboard(40, 30, 200, 60)) < 0.0);
  // Less contrast, same structure: between the two.
  const double softer = ssim(board, checkerboard(40, 30, 100, 160));
  CHECK(softer > 0.5);
  CHECK(softer < 1.0);
  // Symmetric in its arguments.
  CHECK(ssim(checkerboard(40, 30, 100, 160), board) == doctest::Approx(softer).epsilon(1e-12));
}

}  // namespace triwalk
