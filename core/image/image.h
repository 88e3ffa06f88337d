#pragma once
// Plain row-major images. Row 0 is the top of the picture.

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace triwalk {

template <typename Pixel>
struct Image {
  int width = 0;
  int height = 0;
  std::vector<Pixel> pixels;

  Image() = default;
  Image(int imageWidth, int imageHeight, Pixel fill = Pixel{})
      : width(imageWidth), height(imageHeight), pixels(size_t(imageWidth) * size_t(imageHeight), fill) {}

  Pixel& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  const Pixel& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
  size_t pixelCount() const { return pixels.size(); }
  bool empty() const { return pixels.empty(); }
};

using ColorImage = Image<glm::vec3>;        // linear RGB unless stated
using ScalarImage = Image<float>;
using Rgb8Image = Image<glm::u8vec3>;       // display (sRGB-encoded) pixels

// One RGB-D panorama: linear color and Euclidean distance in metres along
// each pixel's direction (+inf where there is no surface).
struct Panorama {
  ColorImage color;
  ScalarImage distance;

  int width() const { return color.width; }
  int height() const { return color.height; }
};

}  // namespace triwalk
