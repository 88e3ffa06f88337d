#include "core/image/color.h"

#include <array>

namespace triwalk {

std::array<float, kSrgbTableIntervals + 2> makeSrgbTable() {
  std::array<float, kSrgbTableIntervals + 2> table{};
  for (int i = 0; i <= kSrgbTableIntervals; ++i) table[size_t(i)] = linearToSrgb(float(i) / kSrgbTableIntervals);
  table[kSrgbTableIntervals + 1] = table[kSrgbTableIntervals];
  return table;
}

glm::vec3 falseColor(float t) {
  // Polynomial approximation of Google's Turbo colormap (Apache-2.0 published
  // coefficients), evaluated in display space.
  const float x = std::clamp(t, 0.0f, 1.0f);
  const glm::vec4 v4(1.0f, x, x * x, x * x * x);
  const glm::vec2 v2(v4.z * v4.z, v4.w * v4.z);
  const glm::vec4 red4(0.13572138f, 4.61539260f, -42.66032258f, 132.13108234f);
  const glm::vec4 green4(0.09140261f, 2.19418839f, 4.84296658f, -14.18503333f);
  const glm::vec4 blue4(0.10667330f, 12.64194608f, -60.58204836f, 110.36276771f);
  const glm::vec2 red2(-152.94239396f, 59.28637943f);
  const glm::vec2 green2(4.27729857f, 2.82956604f);
  const glm::vec2 blue2(-89.90310912f, 27.34824973f);
  const glm::vec3 color(glm::dot(v4, red4) + glm::dot(v2, red2), glm::dot(v4, green4) + glm::dot(v2, green2),
                        glm::dot(v4, blue4) + glm::dot(v2, blue2));
  return glm::clamp(color, 0.0f, 1.0f);
}

}  // namespace triwalk
