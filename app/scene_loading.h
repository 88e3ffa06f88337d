#pragma once
// --scene for capture and bench: the built-in scene, a JSON scene
// description, or any file Assimp reads, with its import options.

#include "render/scene.h"

#include <CLI/CLI.hpp>

#include <string>

namespace triwalk {

struct SceneImportArguments {
  float unitScale = 1.0f;
  std::string upAxis = "z";
};

void addSceneImportOptions(CLI::App& command, SceneImportArguments& arguments);

struct LoadedScene {
  std::string name;
  Scene scene;
};

LoadedScene loadSceneForCapture(const std::string& spec, const SceneImportArguments& arguments);

}  // namespace triwalk
