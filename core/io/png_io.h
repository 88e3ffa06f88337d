#pragma once
// PNG and general image decoding through stb (stb_image_write, stb_image).
// PNGs always hold display values (sRGB-encoded bytes).

#include "core/image/image.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace triwalk {

// Writes atomically (temporary file + rename).
void writePng(const std::filesystem::path& path, const Rgb8Image& image);

// Reads any 8-bit RGB(A) PNG; alpha is dropped.
Rgb8Image readPng(const std::filesystem::path& path);

// 8-bit RGBA decoded from an in-memory file (PNG, JPEG, TGA, BMP, ...);
// subject names the source in errors.
struct Rgba8Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;
};
Rgba8Image decodeImage(std::span<const uint8_t> bytes, const std::string& subject);

// Linear color to display bytes.
Rgb8Image toDisplayImage(const ColorImage& linear);

// Distance in false color, near = blue, far = red; +inf (sky) is black.
Rgb8Image distanceFalseColorImage(const ScalarImage& distance, float maxDistance);

// Scalar values in [0, maxValue] in false color.
Rgb8Image heatmapImage(const ScalarImage& values, float maxValue);

// Side-by-side composition of images of equal height.
Rgb8Image concatenateHorizontally(std::span<const Rgb8Image> images);

}  // namespace triwalk
