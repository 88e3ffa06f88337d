#include "core/synthesis/hole_fill.h"

#include "core/image/color.h"
#include "core/support/errors.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace triwalk {

HoleMode parseHoleMode(const std::string& name) {
  if (name == "fill") return HoleMode::Fill;
  if (name == "mark") return HoleMode::Mark;
  if (name == "black") return HoleMode::Black;
  throw InputError("holes", "unknown hole mode '" + name + "' (use fill, mark or black)");
}

const char* holeModeName(HoleMode mode) {
  switch (mode) {
    case HoleMode::Fill: return "fill";
    case HoleMode::Mark: return "mark";
    case HoleMode::Black: return "black";
  }
  return "?";
}

glm::vec3 holeDisplayColor(HoleMode mode) {
  return mode == HoleMode::Mark ? glm::vec3(1.0f, 0.0f, 1.0f) : glm::vec3(0.0f);
}

Rgb8Image displayImage(const BlendedView& view, HoleMode mode) {
  Rgb8Image image(view.color.width, view.color.height);
  for (size_t i = 0; i < image.pixelCount(); ++i) {
    image.pixels[i] = toBytes(view.hole[i] ? holeDisplayColor(mode) : displayColor(view.color.pixels[i]));
  }
  return image;
}

namespace {

// A pyramid level as the GPU stores it: linear rgb and the inverse
// distance (0 for sky, negative where nothing is known).
struct Level {
  int width = 0, height = 0;
  std::vector<glm::vec4> texels;
  glm::vec4 at(int x, int y) const { return texels[size_t(y) * size_t(width) + size_t(x)]; }
};

constexpr float kUnknown = -1.0f;

// The weighted mean of the candidates on the farthest surface among the
// known ones (inverse distance within (1 + epsilon) of the smallest);
// unknown when none is known. Shared by push (equal weights) and pull
// (bilinear weights), as in the shaders.
glm::vec4 farthestSurfaceMean(const glm::vec4* candidates, const float* weights, int count, float epsilon) {
  float nearestInverse = INFINITY;
  for (int i = 0; i < count; ++i) {
    if (candidates[i].a >= 0.0f) nearestInverse = std::min(nearestInverse, candidates[i].a);
  }
  if (std::isinf(nearestInverse)) return glm::vec4(0.0f, 0.0f, 0.0f, kUnknown);
  const float limit = nearestInverse * (1.0f + epsilon);
  glm::vec4 sum(0.0f);
  float weightSum = 0.0f;
  for (int i = 0; i < count; ++i) {
    if (candidates[i].a < 0.0f || candidates[i].a > limit) continue;
    sum += weights[i] * candidates[i];
    weightSum += weights[i];
  }
  return sum / weightSum;
}

// The push's mean: sky (q = 0) is farther than any surface, so a single
// sky child would make the whole coarser texel sky, and sky seen through a
// small opening would spread over every coarser level and into holes on
// the wall around it; sky counts only where it is not outnumbered by
// surfaces (weights summed), as in the shaders.
glm::vec4 farthestSurfaceMeanOfMajority(glm::vec4* candidates, const float* weights, int count, float epsilon) {
  float sky = 0.0f, surface = 0.0f;
  for (int i = 0; i < count; ++i) {
    if (candidates[i].a == 0.0f) sky += weights[i];
    if (candidates[i].a > 0.0f) surface += weights[i];
  }
  if (surface > sky) {
    for (int i = 0; i < count; ++i) {
      if (candidates[i].a == 0.0f) candidates[i] = glm::vec4(0.0f, 0.0f, 0.0f, kUnknown);
    }
  }
  return farthestSurfaceMean(candidates, weights, count, epsilon);
}

Level push(const Level& finer, float epsilon) {
  Level coarser{(finer.width + 1) / 2, (finer.height + 1) / 2, {}};
  coarser.texels.resize(size_t(coarser.width) * size_t(coarser.height));
  tbb::parallel_for(0, coarser.height, [&](int y) {
    for (int x = 0; x < coarser.width; ++x) {
      glm::vec4 children[4];
      const float weights[4] = {1.0f, 1.0f, 1.0f, 1.0f};
      int count = 0;
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          const int cx = 2 * x + dx, cy = 2 * y + dy;
          if (cx < finer.width && cy < finer.height) children[count++] = finer.at(cx, cy);
        }
      }
      coarser.texels[size_t(y) * size_t(coarser.width) + size_t(x)] =
          farthestSurfaceMeanOfMajority(children, weights, count, epsilon);
    }
  });
  return coarser;
}

// Fills the unknown texels of level from the already filled coarser one.
void pull(Level& level, const Level& coarser, float epsilon) {
  tbb::parallel_for(0, level.height, [&](int y) {
    for (int x = 0; x < level.width; ++x) {
      glm::vec4& texel = level.texels[size_t(y) * size_t(level.width) + size_t(x)];
      if (texel.a >= 0.0f) continue;
      // The pixel centre in coarser texel coordinates is (x + 0.5) / 2 - 0.5:
      // the nearer coarser texel weighs 3/4 along each axis.
      const int baseX = x % 2 == 0 ? x / 2 - 1 : x / 2, baseY = y % 2 == 0 ? y / 2 - 1 : y / 2;
      const float fx = x % 2 == 0 ? 0.75f : 0.25f, fy = y % 2 == 0 ? 0.75f : 0.25f;
      glm::vec4 parents[4];
      float weights[4];
      int count = 0;
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          const int px = std::clamp(baseX + dx, 0, coarser.width - 1), py = std::clamp(baseY + dy, 0, coarser.height - 1);
          parents[count] = coarser.at(px, py);
          weights[count++] = (dx == 0 ? 1.0f - fx : fx) * (dy == 0 ? 1.0f - fy : fy);
        }
      }
      texel = farthestSurfaceMean(parents, weights, count, epsilon);
    }
  });
}

}  // namespace

HoleFillStatistics fillHoles(BlendedView& view, float epsilon) {
  HoleFillStatistics statistics;
  const size_t pixels = view.hole.size();
  statistics.holesBefore = size_t(std::count(view.hole.begin(), view.hole.end(), uint8_t(1)));
  if (statistics.holesBefore == 0) return statistics;

  std::vector<Level> levels(1);
  levels[0] = {view.color.width, view.color.height, std::vector<glm::vec4>(pixels)};
  for (size_t i = 0; i < pixels; ++i) {
    const float distance = view.distance.pixels[i];
    const float inverse = view.hole[i] ? kUnknown : std::isinf(distance) ? 0.0f : 1.0f / distance;
    levels[0].texels[i] = glm::vec4(view.color.pixels[i], inverse);
  }
  while (levels.back().width > 1 || levels.back().height > 1) levels.push_back(push(levels.back(), epsilon));
  for (size_t l = levels.size() - 1; l-- > 0;) pull(levels[l], levels[l + 1], epsilon);

  for (size_t i = 0; i < pixels; ++i) {
    if (!view.hole[i]) continue;
    const glm::vec4 texel = levels[0].texels[i];
    if (texel.a < 0.0f) {
      ++statistics.unfilled;
      continue;
    }
    view.hole[i] = 0;
    view.color.pixels[i] = glm::vec3(texel);
    view.distance.pixels[i] = texel.a > 0.0f ? 1.0f / texel.a : INFINITY;
  }
  return statistics;
}

}  // namespace triwalk
