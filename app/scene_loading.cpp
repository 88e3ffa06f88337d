#include "app/scene_loading.h"

#include "core/errors.h"
#include "render/scene_description.h"

#include <filesystem>

namespace triwalk {

void addSceneImportOptions(CLI::App& command, SceneImportArguments& arguments) {
  command.add_option("--unit-scale", arguments.unitScale, "Metres per scene unit (imported scenes)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  command.add_option("--up-axis", arguments.upAxis, "Up axis of an imported scene: x, y or z")
      ->capture_default_str()->check(CLI::IsMember({"x", "y", "z"}));
}

LoadedScene loadSceneForCapture(const std::string& spec, const SceneImportArguments&) {
  if (spec == "builtin") return {"builtin", loadSceneDescription(builtinScenePath())};
  const std::filesystem::path path(spec);
  if (!std::filesystem::exists(path)) throw InputError(spec, "scene file does not exist");
  if (path.extension() == ".json") return {path.stem().string(), loadSceneDescription(path)};
  throw InputError(spec, "unsupported scene format '" + path.extension().string() + "'");
}

}  // namespace triwalk
