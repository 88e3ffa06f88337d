#include "scene/scene.h"

#include <algorithm>
#include <limits>

namespace triwalk {

size_t Scene::triangleCount() const {
  size_t count = 0;
  for (const SceneMesh& mesh : meshes) count += mesh.indices.size() / 3;
  return count;
}

size_t Scene::vertexCount() const {
  size_t count = 0;
  for (const SceneMesh& mesh : meshes) count += mesh.vertices.size();
  return count;
}

size_t Scene::passableMeshCount() const {
  return size_t(std::count_if(meshes.begin(), meshes.end(),
                              [&](const SceneMesh& mesh) { return materials[size_t(mesh.material)].passable; }));
}

Scene withDoorsOpen(Scene scene) {
  std::erase_if(scene.meshes, [&](const SceneMesh& mesh) { return scene.materials[size_t(mesh.material)].passable; });
  return scene;
}

void Scene::bounds(glm::vec3& lower, glm::vec3& upper) const {
  lower = glm::vec3(std::numeric_limits<float>::max());
  upper = glm::vec3(std::numeric_limits<float>::lowest());
  for (const SceneMesh& mesh : meshes) {
    for (const SceneVertex& vertex : mesh.vertices) {
      lower = glm::min(lower, vertex.position);
      upper = glm::max(upper, vertex.position);
    }
  }
}

}  // namespace triwalk
