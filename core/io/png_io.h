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

// The size of any image stb can read (PNG, JPEG, ...), from its header
// alone, so a whole capture can be checked before any pixel is decoded.
glm::ivec2 imageFileSize(const std::filesystem::path& path);

// A 16-bit single-channel PNG (depth maps of RGB-D captures). Reading
// refuses 8-bit or multi-channel files: widening them would silently
// change the values' meaning.
using Gray16Image = Image<uint16_t>;
Gray16Image readPng16(const std::filesystem::path& path);
// Writes atomically, through libpng (stb writes only 8 bits).
void writePng16(const std::filesystem::path& path, const Gray16Image& image);

// Linear color to display bytes.
Rgb8Image toDisplayImage(const ColorImage& linear);

// Distance in false color, near = blue, far = red; +inf (sky) is black.
Rgb8Image distanceFalseColorImage(const ScalarImage& distance, float maxDistance);

// Scalar values in [0, maxValue] in false color.
Rgb8Image heatmapImage(const ScalarImage& values, float maxValue);

// Side-by-side composition of images of equal height.
Rgb8Image concatenateHorizontally(std::span<const Rgb8Image> images);

}  // namespace triwalk
