#pragma once
// --scene for capture and bench: the built-in scene, a generated floor
// (builtin-floor:CxR[:SEED]), a JSON scene description, or any file
// Assimp reads, with its import options.

#include "core/geometry/walkable_region.h"
#include "core/io/dataset.h"
#include "scene/assimp_scene.h"
#include "scene/scene.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

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

// What a capture keeps of --scene and the import options so that the
// scene can be loaded again from the data set: {"spec": S, "unit_scale",
// "up_axis", "map"}, a file's spec made absolute.
nlohmann::json sceneSource(const std::string& spec, const SceneImportArguments& arguments);

// The scene a data set was captured from, as its capture drew it (doors
// open unless it closed them): for `render --truth`. Throws InputError
// naming the manifest when the data set keeps no scene (imported from
// panoramas, or captured before captures kept it) or the scene file is gone.
Scene loadCapturedScene(const Dataset& dataset);

}  // namespace triwalk
