#pragma once
// Procedural surface patterns for the built-in scene, baked into ordinary
// textures so that capture draws every scene the same way. Colors are
// display (sRGB) values; the texture stores sRGB bytes.

#include "scene/scene.h"

#include <string>

namespace triwalk {

enum class PatternKind { Tiles, Bricks, Planks, Plaster, Marble, Checker, Gravel, Grass };

struct PatternSpec {
  PatternKind kind = PatternKind::Plaster;
  glm::vec3 primary{0.8f};    // sRGB
  glm::vec3 secondary{0.5f};  // sRGB: grout, mortar, veins, second tile color...
  int repeats = 4;            // tiles / brick rows / planks per texture
  float variation = 0.15f;    // per-element brightness variation
  float detail = 0.08f;       // amplitude of the fine noise
  int resolution = 512;       // texels per side
  unsigned seed = 1;
};

// Parses a pattern name ("tiles", "bricks", ...); returns false if unknown.
bool parsePatternKind(const std::string& name, PatternKind& kind);

SceneTexture generatePatternTexture(const PatternSpec& spec, const std::string& name);

}  // namespace triwalk
