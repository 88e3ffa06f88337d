#include "app/setup/scene_loading.h"

#include "app/setup/option_checks.h"
#include "core/io/json_fields.h"
#include "core/support/errors.h"
#include "scene/floor_plan.h"
#include "scene/scene_description.h"

#include <cstdio>
#include <filesystem>

namespace triwalk {

void addSceneImportOptions(CLI::App& command, SceneImportArguments& arguments) {
  command.add_option("--unit-scale", arguments.unitScale,
                     "Metres per unit of an imported scene (0: automatic, 0.0254 for Quake 3, else 1)")
      ->capture_default_str()->check(nonNegativeNumber())->group("Import");
  command.add_option("--up-axis", arguments.upAxis, "Up axis of an imported scene: auto, x, y or z")
      ->capture_default_str()->check(CLI::IsMember({"auto", "x", "y", "z"}))->group("Import");
  command.add_option("--map", arguments.map, "Quake 3 archive (.pk3): the map to read, e.g. oacmpdm3 (default: the first)")
      ->group("Import");
}

LoadedScene loadSceneForCapture(const std::string& spec, const SceneImportArguments& arguments) {
  if (spec == "builtin") return {"builtin", loadSceneDescription(builtinScenePath()), false, std::nullopt, std::nullopt};
  if (const std::optional<FloorPlanSize> size = parseFloorPlanSpec(spec)) {
    FloorPlan plan = makeFloorPlan(*size, readJsonFile(builtinScenePath()));
    return {spec, sceneFromDescription(plan.description, spec), false, std::move(plan.region), plan.sampleSpacing};
  }
  const std::filesystem::path path(spec);
  if (!std::filesystem::exists(path)) throw InputError(spec, "scene file does not exist");
  if (path.extension() == ".json") return {path.stem().string(), loadSceneDescription(path), false, std::nullopt, std::nullopt};
  SceneImportOptions options;
  options.unitScale = arguments.unitScale;
  options.upAxis = arguments.upAxis;
  options.map = arguments.map;
  SceneImportReport report;
  LoadedScene loaded{"", importScene(path, options, report), true, std::nullopt, std::nullopt};
  loaded.name = loaded.scene.name;
  std::printf("imported %s: %zu triangles, %zu materials, %d textures", spec.c_str(), loaded.scene.triangleCount(),
              loaded.scene.materials.size(), report.texturesLoaded);
  if (!report.map.empty()) std::printf(", map %s, %zu spawn points", report.map.c_str(), report.spawnPoints.size());
  if (report.doorMeshes > 0) std::printf(", %d meshes of door elements (passable for the walkable region, open in captures)", report.doorMeshes);
  std::printf("\n");
  if (!report.missingTextures.empty()) {
    std::fprintf(stderr, "triwalk: warning: %zu textures not found (drawn in a neutral color), e.g. %s\n",
                 report.missingTextures.size(), report.missingTextures.front().c_str());
  }
  return loaded;
}

nlohmann::json sceneSource(const std::string& spec, const SceneImportArguments& arguments) {
  const bool file = spec != "builtin" && !parseFloorPlanSpec(spec);
  return {{"spec", file ? std::filesystem::absolute(spec).lexically_normal().string() : spec},
          {"unit_scale", arguments.unitScale},
          {"up_axis", arguments.upAxis},
          {"map", arguments.map}};
}

Scene loadCapturedScene(const Dataset& dataset) {
  const std::string manifest = dataset.manifestPath().string();
  const JsonObject capture(dataset.manifest().capture, manifest, "capture");
  const std::string& name = dataset.manifest().scene;
  std::string spec;
  SceneImportArguments arguments;
  if (capture.has("scene")) {
    const JsonObject source = capture.object("scene");
    spec = source.string("spec");
    arguments.unitScale = float(source.numberOr("unit_scale", 0.0));
    arguments.upAxis = source.stringOr("up_axis", "auto");
    arguments.map = source.stringOr("map", "");
    if (!(arguments.unitScale >= 0.0f && arguments.unitScale < 1e6f)) source.fail("unit_scale must be a number from 0 to 1e6");
    if (arguments.upAxis != "auto" && arguments.upAxis != "x" && arguments.upAxis != "y" && arguments.upAxis != "z") {
      source.fail("up_axis must be auto, x, y or z");
    }
    if (spec != "builtin" && !parseFloorPlanSpec(spec) && !std::filesystem::exists(spec)) {
      source.fail("names the scene file " + spec + ", which does not exist");
    }
  } else if (name == "builtin" || parseFloorPlanSpec(name)) {
    spec = name;  // the built-in family is known by its name, also in captures from before the manifest kept the scene
  } else {
    throw InputError(manifest, "keeps no scene to render the truth from (imported from panoramas, or captured before "
                               "captures kept their scene)");
  }
  LoadedScene loaded = loadSceneForCapture(spec, arguments);
  if (loaded.scene.passableMeshCount() > 0 && capture.stringOr("doors", "open") == "open") {
    return withDoorsOpen(std::move(loaded.scene));
  }
  return std::move(loaded.scene);
}

}  // namespace triwalk
