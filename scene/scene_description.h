#pragma once
// Scenes described in JSON (the built-in scene is assets/builtin_scene.json):
// materials with procedural patterns, solids (boxes, walls with openings,
// floors with holes, cylinders, spheres), lights, sky and walkable area.
// The format is documented at the top of assets/builtin_scene.json's
// companion, docs/SCENE_FORMAT.md.

#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace triwalk {

// Builds the scene; throws InputError naming the file on any bad field.
Scene loadSceneDescription(const std::filesystem::path& path);
// The same from a description in memory (a generated floor plan); subject
// names it in errors.
Scene sceneFromDescription(const nlohmann::json& description, const std::string& subject);

// Where the built-in assets live: $TRIWALK_ASSETS, else the source tree's
// assets/ directory recorded at build time.
std::filesystem::path assetDirectory();
std::filesystem::path builtinScenePath();

}  // namespace triwalk
