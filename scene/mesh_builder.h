#pragma once
// Builds tessellated triangle meshes from simple solids (quads, boxes,
// cylinders, spheres) with world-anchored texture coordinates, so patterns
// line up across neighbouring pieces.

#include "scene/scene.h"

namespace triwalk {

class MeshBuilder {
public:
  // textureSize: metres covered by one repeat of the material's texture.
  MeshBuilder(int material, float textureSize);

  // Planar quad origin + s*edgeU + t*edgeV, s,t in [0,1], facing
  // cross(edgeU, edgeV), split into cells no larger than cellSize metres.
  void addQuad(glm::vec3 origin, glm::vec3 edgeU, glm::vec3 edgeV, float cellSize);

  // Axis-aligned box with outward faces; skipBottom leaves out the face at min.z.
  void addBox(glm::vec3 lower, glm::vec3 upper, float cellSize, bool skipBottom = false);

  // Vertical cylinder with outward normals and a top cap.
  void addCylinder(glm::vec2 center, float radius, float bottom, float top, int segments);

  void addSphere(glm::vec3 center, float radius, int segments);

  bool empty() const { return mesh_.indices.empty(); }
  SceneMesh take();

private:
  uint32_t addVertex(glm::vec3 position, glm::vec3 normal, glm::vec2 uv);
  void addGridTriangles(uint32_t first, uint32_t rowLength, int cellsAcross, int cellsDown, bool reverse);

  SceneMesh mesh_;
  float textureSize_;
};

}  // namespace triwalk
