#pragma once
// Scenes in any format Assimp reads (OBJ, glTF, FBX, IFC, Quake 3 levels in
// .pk3, ...), converted to triwalk's world: metres, z up. Materials keep
// their diffuse textures (embedded or files, decoded with stb_image),
// vertex colors and lightmaps (Quake 3); a texture that cannot be found
// becomes a neutral color and is reported, never a failure.

#include "scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace triwalk {

struct SceneImportOptions {
  float unitScale = 0.0f;       // metres per scene unit; 0: 0.0254 for Quake 3 (inches), else 1
  std::string upAxis = "auto";  // x, y, z or auto (z for Quake 3, y otherwise: Assimp's convention)
  std::string map;              // Quake 3 archives: the map (e.g. oacmpdm3); empty: the first
};

struct SceneImportReport {
  std::string map;                          // the Quake 3 map read
  std::vector<std::string> missingTextures;
  int texturesLoaded = 0;
  std::vector<glm::vec3> spawnPoints;       // metres, world frame (Quake 3)
  int doorMeshes = 0;                       // IFC door elements, marked passable
};

// Throws InputError naming the file for a missing, corrupt or unsupported scene.
Scene importScene(const std::filesystem::path& file, const SceneImportOptions& options, SceneImportReport& report);

}  // namespace triwalk
