#pragma once
// Color spaces: the data set stores linear RGB; errors and PNGs use display
// values (sRGB-encoded, clamped to [0, 1]), as docs/DESIGN.md fixes.

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace triwalk {

inline float linearToSrgb(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

inline float srgbToLinear(float encoded) {
  const float c = std::clamp(encoded, 0.0f, 1.0f);
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline glm::vec3 displayColor(glm::vec3 linear) {
  return {linearToSrgb(linear.r), linearToSrgb(linear.g), linearToSrgb(linear.b)};
}

// linearToSrgb through a table (4096 intervals, linear interpolation; at
// most 2e-5 from the exact curve): the error measure converts every pixel
// of every reconstruction.
constexpr int kSrgbTableIntervals = 4096;
std::array<float, kSrgbTableIntervals + 2> makeSrgbTable();
// Inline, so that the per-pixel conversions below read it without a call.
inline const float* srgbTable() {
  static const std::array<float, kSrgbTableIntervals + 2> table = makeSrgbTable();
  return table.data();
}

// NaN maps to 0 (std::clamp would pass it through to the table index).
inline float linearToSrgbFast(float linear) {
  const float x = (linear >= 0.0f ? std::min(linear, 1.0f) : 0.0f) * float(kSrgbTableIntervals);
  const int i = int(x);
  const float* table = srgbTable();
  return table[i] + (x - float(i)) * (table[i + 1] - table[i]);
}

inline glm::vec3 displayColorFast(glm::vec3 linear) {
  return {linearToSrgbFast(linear.r), linearToSrgbFast(linear.g), linearToSrgbFast(linear.b)};
}

// NaN becomes 0: converting it to an integer is undefined.
inline uint8_t toByte(float display) {
  return uint8_t((display >= 0.0f ? std::min(display, 1.0f) : 0.0f) * 255.0f + 0.5f);
}

inline glm::u8vec3 toBytes(glm::vec3 display) { return {toByte(display.r), toByte(display.g), toByte(display.b)}; }

// Perceptually ordered false color for t in [0, 1] (a compact fit of the
// "turbo" colormap); used for distance images and error heatmaps.
glm::vec3 falseColor(float t);

}  // namespace triwalk
