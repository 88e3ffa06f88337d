#pragma once
// --scene for capture and bench: the built-in scene, a generated floor
// (builtin-floor:CxR[:SEED]), a JSON scene description, or any file
// Assimp reads, with its import options.

#include "core/geometry/walkable_region.h"
#include "render/scene/assimp_scene.h"
#include "render/scene/scene.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace triwalk {

struct SceneImportArguments {
  float unitScale = 0.0f;
  std::string upAxis = "auto";
  std::string map;
};

void addSceneImportOptions(CLI::App& command, SceneImportArguments& arguments);

struct LoadedScene {
  std::string name;
  Scene scene;
  bool imported = false;  // by Assimp: no walkable area of its own
  // A generated floor's own walkable region, and the sample spacing its
  // capture takes unless --spacing, --paths or --per-path says otherwise.
  std::optional<WalkableRegion> region;
  std::optional<float> sampleSpacing;
};

// Prints what an import found (map, textures, spawn points).
LoadedScene loadSceneForCapture(const std::string& spec, const SceneImportArguments& arguments);

}  // namespace triwalk
