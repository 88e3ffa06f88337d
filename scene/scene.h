#pragma once
// A renderable scene: triangle meshes with materials, textures, lights and
// a sky, plus where a person can walk. Filled by the built-in scene builder
// (assets/builtin_scene.json) or the Assimp importer; drawn by capture.

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace triwalk {

struct SceneVertex {
  glm::vec3 position{0.0f};  // metres, world frame (z up)
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  glm::vec2 uv{0.0f};
  glm::vec2 lightmapUv{0.0f};
  glm::vec4 color{1.0f};  // linear vertex color
};

// 8-bit RGBA texture; sRGB-encoded unless it holds data (lightmaps are
// stored as they come from the file, also sRGB-encoded in Quake 3).
struct SceneTexture {
  std::string name;
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;
};

struct SceneMaterial {
  std::string name;
  glm::vec3 baseColor{1.0f};  // linear, multiplies texture and vertex color
  int diffuseTexture = -1;    // index into Scene::textures, -1 for none
  int lightmapTexture = -1;   // -1: lit by the scene's ambient and lights
  float lightmapScale = 1.0f;
  float specular = 0.0f;      // Blinn-Phong strength, 0 for matte
  float shininess = 32.0f;
  bool alphaTest = false;     // discard texels with alpha < 0.5
  bool useVertexColor = false;
  // A door leaf (an IFC door element): drawn, but the automatic walkable
  // region passes through it, as a person opens a door.
  bool passable = false;
};

struct SceneMesh {
  int material = 0;
  std::vector<SceneVertex> vertices;
  std::vector<uint32_t> indices;  // triangles
};

struct SceneLight {
  glm::vec3 position{0.0f};
  glm::vec3 color{1.0f};  // linear intensity
  float range = 5.0f;     // metres; falloff 1 / (1 + (d / range)^2)
};

struct SkyModel {
  glm::vec3 zenith{0.25f, 0.45f, 0.85f};
  glm::vec3 horizon{0.75f, 0.85f, 0.95f};
  glm::vec3 ground{0.3f, 0.28f, 0.25f};
  glm::vec3 sunDirection{0.3f, 0.2f, 0.93f};
  glm::vec3 sunColor{8.0f, 7.5f, 6.5f};
};

struct WalkableArea {
  glm::vec2 min{0.0f};
  glm::vec2 max{10.0f, 5.0f};
  float eyeHeight = 1.6f;  // metres above the floor at z = floorHeight
  float floorHeight = 0.0f;
};

struct Scene {
  std::string name;
  std::vector<SceneMesh> meshes;
  std::vector<SceneMaterial> materials;
  std::vector<SceneTexture> textures;
  std::vector<SceneLight> lights;
  glm::vec3 ambient{0.3f};
  SkyModel sky;
  WalkableArea walkableArea;
  std::vector<glm::vec3> spawnPoints;  // from the level, when it has them

  size_t triangleCount() const;
  size_t vertexCount() const;
  size_t passableMeshCount() const;
  // Axis-aligned bounds of all vertices, metres.
  void bounds(glm::vec3& lower, glm::vec3& upper) const;
};

// The scene with its doors open, as a walker passes them: without the
// passable meshes (door leaves).
Scene withDoorsOpen(Scene scene);

}  // namespace triwalk
