#include "scene/procedural_texture.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace triwalk {

namespace {

// Integer hash (a variant of the "lowbias32" mixer) -> [0, 1).
float hashToUnit(unsigned x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return float(x & 0xFFFFFFU) / float(0x1000000);
}

float hash2(int x, int y, unsigned seed) { return hashToUnit(unsigned(x) * 73856093U ^ unsigned(y) * 19349663U ^ seed * 83492791U); }

// Smooth value noise, periodic with the given period (in lattice cells) so
// textures tile without seams.
float valueNoise(float x, float y, int period, unsigned seed) {
  const int x0 = int(std::floor(x));
  const int y0 = int(std::floor(y));
  const float fx = x - float(x0);
  const float fy = y - float(y0);
  auto lattice = [&](int i, int j) {
    return hash2(((i % period) + period) % period, ((j % period) + period) % period, seed);
  };
  const float sx = fx * fx * (3.0f - 2.0f * fx);
  const float sy = fy * fy * (3.0f - 2.0f * fy);
  const float top = glm::mix(lattice(x0, y0), lattice(x0 + 1, y0), sx);
  const float bottom = glm::mix(lattice(x0, y0 + 1), lattice(x0 + 1, y0 + 1), sx);
  return glm::mix(top, bottom, sy);
}

// Fractal noise in [0, 1] over the unit square (u, v in [0, 1)), tiling.
float fractalNoise(float u, float v, int baseFrequency, int octaves, unsigned seed) {
  float sum = 0.0f, amplitude = 0.5f, norm = 0.0f;
  int frequency = baseFrequency;
  for (int octave = 0; octave < octaves; ++octave) {
    sum += amplitude * valueNoise(u * float(frequency), v * float(frequency), frequency, seed + unsigned(octave));
    norm += amplitude;
    amplitude *= 0.5f;
    frequency *= 2;
  }
  return sum / norm;
}

struct TexelContext {
  const PatternSpec& spec;
  float u, v;  // [0, 1)
  float fine;  // fine noise in [-1, 1]
};

glm::vec3 tiles(const TexelContext& c) {
  const float n = float(c.spec.repeats);
  const float tu = c.u * n, tv = c.v * n;
  const int iu = int(tu), iv = int(tv);
  const float fu = tu - float(iu), fv = tv - float(iv);
  const float grout = 0.04f;
  if (fu < grout || fv < grout) return c.spec.secondary * (0.9f + 0.1f * c.fine);
  const glm::vec3 base = ((iu + iv) % 2 == 0) ? c.spec.primary : glm::mix(c.spec.primary, c.spec.secondary, 0.35f);
  const float tileShade = 1.0f + c.spec.variation * (hash2(iu, iv, c.spec.seed) - 0.5f) * 2.0f;
  return base * tileShade * (1.0f + c.spec.detail * c.fine);
}

glm::vec3 bricks(const TexelContext& c) {
  const float rows = float(c.spec.repeats);
  const float bricksPerRow = rows / 2.0f;
  const float tv = c.v * rows;
  const int row = int(tv);
  const float tu = c.u * bricksPerRow + ((row % 2) ? 0.5f : 0.0f);
  const int column = int(std::floor(tu));
  const float fu = tu - float(column), fv = tv - float(row);
  if (fv < 0.08f || fu < 0.04f) return c.spec.secondary * (0.85f + 0.15f * c.fine);
  const float brickShade = 1.0f + c.spec.variation * (hash2(column, row, c.spec.seed) - 0.5f) * 2.0f;
  return c.spec.primary * brickShade * (1.0f + c.spec.detail * c.fine);
}

glm::vec3 planks(const TexelContext& c) {
  const float n = float(c.spec.repeats);
  const float tv = c.v * n;
  const int plank = int(tv);
  const float fv = tv - float(plank);
  if (fv < 0.03f) return c.spec.secondary * 0.6f;
  const float offset = hash2(plank, 7, c.spec.seed);
  const float grainNoise = fractalNoise(c.u, c.v, 4, 3, c.spec.seed + 11);
  const float grain = 0.5f + 0.5f * std::sin((c.u * 2.0f + offset) * 60.0f + grainNoise * 12.0f + fv * 3.0f);
  const float plankShade = 1.0f + c.spec.variation * (offset - 0.5f) * 2.0f;
  return glm::mix(c.spec.primary, c.spec.secondary, 0.55f * grain) * plankShade * (1.0f + c.spec.detail * c.fine);
}

glm::vec3 plaster(const TexelContext& c) {
  const float broad = fractalNoise(c.u, c.v, 4, 3, c.spec.seed + 3) - 0.5f;
  return c.spec.primary * (1.0f + c.spec.variation * broad * 2.0f + c.spec.detail * c.fine);
}

glm::vec3 marble(const TexelContext& c) {
  const float turbulence = fractalNoise(c.u, c.v, 4, 5, c.spec.seed + 5);
  const float veins = std::pow(std::abs(std::sin((c.u + c.v) * glm::pi<float>() * 2.0f * float(c.spec.repeats) +
                                                 turbulence * 9.0f)),
                               0.25f);
  return glm::mix(c.spec.secondary, c.spec.primary, veins) * (1.0f + c.spec.detail * c.fine);
}

glm::vec3 checker(const TexelContext& c) {
  const int n = c.spec.repeats;
  const int iu = int(c.u * float(n)), iv = int(c.v * float(n));
  return ((iu + iv) % 2 == 0 ? c.spec.primary : c.spec.secondary) * (1.0f + c.spec.detail * c.fine);
}

glm::vec3 gravel(const TexelContext& c) {
  const float stones = fractalNoise(c.u, c.v, 32, 2, c.spec.seed + 9);
  const glm::vec3 base = glm::mix(c.spec.secondary, c.spec.primary, glm::smoothstep(0.35f, 0.65f, stones));
  return base * (1.0f + c.spec.detail * c.fine);
}

glm::vec3 grass(const TexelContext& c) {
  const float clumps = fractalNoise(c.u, c.v, 8, 4, c.spec.seed + 13);
  const float blades = hash2(int(c.u * 512.0f), int(c.v * 171.0f), c.spec.seed + 17);
  return glm::mix(c.spec.secondary, c.spec.primary, clumps) * (0.8f + 0.4f * blades);
}

}  // namespace

bool parsePatternKind(const std::string& name, PatternKind& kind) {
  static const std::map<std::string, PatternKind> kinds = {
      {"tiles", PatternKind::Tiles},     {"bricks", PatternKind::Bricks},   {"planks", PatternKind::Planks},
      {"plaster", PatternKind::Plaster}, {"marble", PatternKind::Marble},   {"checker", PatternKind::Checker},
      {"gravel", PatternKind::Gravel},   {"grass", PatternKind::Grass}};
  auto it = kinds.find(name);
  if (it == kinds.end()) return false;
  kind = it->second;
  return true;
}

SceneTexture generatePatternTexture(const PatternSpec& spec, const std::string& name) {
  const int size = spec.resolution;
  SceneTexture texture{name, size, size, std::vector<uint8_t>(size_t(size) * size_t(size) * 4)};
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const float u = (float(x) + 0.5f) / float(size);
      const float v = (float(y) + 0.5f) / float(size);
      const float fine = 2.0f * fractalNoise(u, v, 64, 3, spec.seed + 101) - 1.0f;
      const TexelContext context{spec, u, v, fine};
      glm::vec3 color;
      switch (spec.kind) {
        case PatternKind::Tiles: color = tiles(context); break;
        case PatternKind::Bricks: color = bricks(context); break;
        case PatternKind::Planks: color = planks(context); break;
        case PatternKind::Plaster: color = plaster(context); break;
        case PatternKind::Marble: color = marble(context); break;
        case PatternKind::Checker: color = checker(context); break;
        case PatternKind::Gravel: color = gravel(context); break;
        case PatternKind::Grass: color = grass(context); break;
      }
      color = glm::clamp(color, 0.0f, 1.0f);
      uint8_t* texel = &texture.rgba[(size_t(y) * size_t(size) + size_t(x)) * 4];
      texel[0] = uint8_t(color.r * 255.0f + 0.5f);
      texel[1] = uint8_t(color.g * 255.0f + 0.5f);
      texel[2] = uint8_t(color.b * 255.0f + 0.5f);
      texel[3] = 255;
    }
  }
  return texture;
}

}  // namespace triwalk
