#include "core/image/image_annotation.h"

#include "core/image/color.h"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace triwalk {

namespace {

// stb_easy_font's vertex: x, y, z, then a colour it repeats from the call.
struct EasyFontVertex {
  float x, y, z;
  unsigned char color[4];
};

void fillRectangle(Rgb8Image& image, int x0, int y0, int x1, int y1, glm::u8vec3 color) {
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y) {
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) image.at(x, y) = color;
  }
}

}  // namespace

int textHeight(int scale) { return 12 * scale; }

int textWidth(const std::string& text, int scale) {
  std::string copy = text;
  return stb_easy_font_width(copy.data()) * scale;
}

void drawText(Rgb8Image& image, glm::ivec2 at, const std::string& text, glm::u8vec3 color, int scale) {
  std::string copy = text;
  // 4 vertices a quad, at most about 70 quads a character.
  std::vector<EasyFontVertex> vertices(text.size() * 70 * 4 + 4);
  unsigned char unused[4] = {0, 0, 0, 255};
  const int quads = stb_easy_font_print(0.0f, 0.0f, copy.data(), unused, vertices.data(),
                                        int(vertices.size() * sizeof(EasyFontVertex)));
  // Every quad is an axis-aligned rectangle: its first and third corners.
  for (int q = 0; q < quads; ++q) {
    const EasyFontVertex& a = vertices[size_t(q) * 4];
    const EasyFontVertex& c = vertices[size_t(q) * 4 + 2];
    fillRectangle(image, at.x + int(a.x) * scale, at.y + int(a.y) * scale, at.x + int(c.x) * scale,
                  at.y + int(c.y) * scale, color);
  }
}

Rgb8Image withColourBar(const Rgb8Image& image, float maxValue, const std::string& quantity) {
  const int scale = std::max(1, image.width / 600);
  const int margin = 4 * scale, barHeight = 10 * scale, line = textHeight(scale);
  Rgb8Image result(image.width, image.height + margin + barHeight + margin + line + margin, glm::u8vec3(255));
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) result.at(x, y) = image.at(x, y);
  }
  char high[32];
  std::snprintf(high, sizeof high, "%g", double(maxValue));
  const int left = margin + textWidth("0", scale) + margin;
  const int right = image.width - margin - textWidth(high, scale) - margin;
  const int barTop = image.height + margin;
  for (int x = left; x < right; ++x) {
    const glm::u8vec3 color = toBytes(falseColor(float(x - left) / float(std::max(1, right - left - 1))));
    fillRectangle(result, x, barTop, x + 1, barTop + barHeight, color);
  }
  const int labelTop = barTop + (barHeight - line) / 2 + 2 * scale;
  drawText(result, {margin, labelTop}, "0", glm::u8vec3(0), scale);
  drawText(result, {right + margin, labelTop}, high, glm::u8vec3(0), scale);
  const int quantityWidth = textWidth(quantity, scale);
  drawText(result, {std::max(margin, (image.width - quantityWidth) / 2), barTop + barHeight + margin}, quantity,
           glm::u8vec3(0), scale);
  return result;
}

}  // namespace triwalk
