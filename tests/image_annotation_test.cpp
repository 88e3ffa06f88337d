// Labels and colour bars drawn into images (core/image/image_annotation.h):
// the text lands where it is asked and nowhere else, and a heatmap's bar
// runs through the same colours as the heatmap, from 0 to its maximum.

#include "core/image/color.h"
#include "core/image/image_annotation.h"

#include <doctest/doctest.h>

using namespace triwalk;

namespace {

size_t darkPixels(const Rgb8Image& image, int x0, int y0, int x1, int y1) {
  size_t count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) count += image.at(x, y) == glm::u8vec3(0);
  }
  return count;
}

}  // namespace

TEST_CASE("text is drawn inside its box, scaled, and cut at the image's edge") {
  Rgb8Image image(200, 60, glm::u8vec3(255));
  const int width = textWidth("probe 12", 2);
  CHECK(width == 2 * textWidth("probe 12", 1));
  drawText(image, {10, 10}, "probe 12", glm::u8vec3(0), 2);
  const size_t inside = darkPixels(image, 10, 10, 10 + width, 10 + textHeight(2));
  CHECK(inside > 100);
  CHECK(darkPixels(image, 0, 0, 200, 60) == inside);
  // Past the right edge: drawn up to it, no write outside the image.
  drawText(image, {190, 40}, "cut", glm::u8vec3(0), 2);
  CHECK(darkPixels(image, 190, 40, 200, 60) > 0);
}

TEST_CASE("a heatmap's colour bar runs from falseColor(0) to falseColor(1) under the image, with its labels") {
  const Rgb8Image heatmap(300, 100, glm::u8vec3(10, 20, 30));
  const Rgb8Image barred = withColourBar(heatmap, 0.25f, "RMS difference");
  REQUIRE(barred.height > heatmap.height + 20);
  CHECK(barred.width == heatmap.width);
  CHECK(barred.at(150, 50) == glm::u8vec3(10, 20, 30));  // the image itself is unchanged
  // The bar's row: its leftmost coloured pixel is the scale's 0, its rightmost the maximum.
  const int row = heatmap.height + 6;
  int first = -1, last = -1;
  for (int x = 0; x < barred.width; ++x) {
    if (barred.at(x, row) != glm::u8vec3(255) && barred.at(x, row) != glm::u8vec3(0)) {
      if (first < 0) first = x;
      last = x;
    }
  }
  REQUIRE(first >= 0);
  CHECK(barred.at(first, row) == toBytes(falseColor(0.0f)));
  CHECK(barred.at(last, row) == toBytes(falseColor(1.0f)));
  CHECK(last - first > barred.width / 2);
  // "0" left of the bar, "0.25" right of it, the quantity below.
  CHECK(darkPixels(barred, 0, heatmap.height, first, barred.height) > 0);
  CHECK(darkPixels(barred, last + 1, heatmap.height, barred.width, barred.height) > 0);
  CHECK(darkPixels(barred, first, row + 8, last, barred.height) > 0);
}
