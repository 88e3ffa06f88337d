#include "scene/mesh_builder.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace triwalk {

// Two triangles for each cell of a grid of vertices laid out row by row
// from first, rowLength vertices a row; reverse flips their facing.
void MeshBuilder::addGridTriangles(uint32_t first, uint32_t rowLength, int cellsAcross, int cellsDown, bool reverse) {
  for (int j = 0; j < cellsDown; ++j) {
    for (int i = 0; i < cellsAcross; ++i) {
      const uint32_t a = first + uint32_t(j) * rowLength + uint32_t(i);
      const uint32_t b = a + 1, c = a + rowLength, d = c + 1;
      if (reverse) {
        mesh_.indices.insert(mesh_.indices.end(), {a, c, d, a, d, b});
      } else {
        mesh_.indices.insert(mesh_.indices.end(), {a, b, d, a, d, c});
      }
    }
  }
}

MeshBuilder::MeshBuilder(int material, float textureSize) : textureSize_(textureSize) { mesh_.material = material; }

uint32_t MeshBuilder::addVertex(glm::vec3 position, glm::vec3 normal, glm::vec2 uv) {
  SceneVertex vertex;
  vertex.position = position;
  vertex.normal = normal;
  vertex.uv = uv / textureSize_;
  mesh_.vertices.push_back(vertex);
  return uint32_t(mesh_.vertices.size() - 1);
}

void MeshBuilder::addQuad(glm::vec3 origin, glm::vec3 edgeU, glm::vec3 edgeV, float cellSize) {
  const float lengthU = glm::length(edgeU);
  const float lengthV = glm::length(edgeV);
  if (lengthU <= 0.0f || lengthV <= 0.0f) return;
  const glm::vec3 normal = glm::normalize(glm::cross(edgeU, edgeV));
  const glm::vec3 axisU = edgeU / lengthU;
  const glm::vec3 axisV = edgeV / lengthV;
  const int cellsU = std::max(1, int(std::ceil(lengthU / cellSize - 1e-4f)));
  const int cellsV = std::max(1, int(std::ceil(lengthV / cellSize - 1e-4f)));
  const uint32_t first = uint32_t(mesh_.vertices.size());
  for (int j = 0; j <= cellsV; ++j) {
    for (int i = 0; i <= cellsU; ++i) {
      const glm::vec3 p = origin + edgeU * (float(i) / float(cellsU)) + edgeV * (float(j) / float(cellsV));
      // World-anchored coordinates along the quad's own axes.
      addVertex(p, normal, {glm::dot(p, axisU), glm::dot(p, axisV)});
    }
  }
  addGridTriangles(first, uint32_t(cellsU + 1), cellsU, cellsV, false);
}

void MeshBuilder::addBox(glm::vec3 lower, glm::vec3 upper, float cellSize, bool skipBottom) {
  const glm::vec3 size = upper - lower;
  const glm::vec3 x(size.x, 0, 0), y(0, size.y, 0), z(0, 0, size.z);
  addQuad(lower, z, y, cellSize);                                 // -x
  addQuad(glm::vec3(upper.x, lower.y, lower.z), y, z, cellSize);  // +x
  addQuad(lower, x, z, cellSize);                                 // -y
  addQuad(glm::vec3(lower.x, upper.y, lower.z), z, x, cellSize);  // +y
  if (!skipBottom) addQuad(lower, y, x, cellSize);                 // -z
  addQuad(glm::vec3(lower.x, lower.y, upper.z), x, y, cellSize);   // +z
}

void MeshBuilder::addCylinder(glm::vec2 center, float radius, float bottom, float top, int segments) {
  const float circumference = 2.0f * glm::pi<float>() * radius;
  const int rings = std::max(1, int(std::ceil((top - bottom) / 0.25f)));
  const uint32_t first = uint32_t(mesh_.vertices.size());
  for (int ring = 0; ring <= rings; ++ring) {
    const float z = bottom + (top - bottom) * float(ring) / float(rings);
    for (int s = 0; s <= segments; ++s) {
      const float angle = 2.0f * glm::pi<float>() * float(s) / float(segments);
      const glm::vec3 normal(std::cos(angle), std::sin(angle), 0.0f);
      addVertex(glm::vec3(center, z) + radius * normal, normal,
                {circumference * float(s) / float(segments), z});
    }
  }
  addGridTriangles(first, uint32_t(segments + 1), segments, rings, false);
  const uint32_t capCenter = addVertex(glm::vec3(center, top), {0, 0, 1}, center);
  const uint32_t capFirst = uint32_t(mesh_.vertices.size());
  for (int s = 0; s <= segments; ++s) {
    const float angle = 2.0f * glm::pi<float>() * float(s) / float(segments);
    const glm::vec2 p = center + radius * glm::vec2(std::cos(angle), std::sin(angle));
    addVertex(glm::vec3(p, top), {0, 0, 1}, p);
  }
  for (int s = 0; s < segments; ++s) {
    mesh_.indices.insert(mesh_.indices.end(), {capCenter, capFirst + uint32_t(s), capFirst + uint32_t(s) + 1});
  }
}

void MeshBuilder::addSphere(glm::vec3 center, float radius, int segments) {
  const int rings = std::max(2, segments / 2);
  const uint32_t first = uint32_t(mesh_.vertices.size());
  for (int ring = 0; ring <= rings; ++ring) {
    const float latitude = glm::pi<float>() * (0.5f - float(ring) / float(rings));
    for (int s = 0; s <= segments; ++s) {
      const float longitude = 2.0f * glm::pi<float>() * float(s) / float(segments);
      const glm::vec3 normal(std::cos(latitude) * std::cos(longitude), std::cos(latitude) * std::sin(longitude),
                             std::sin(latitude));
      addVertex(center + radius * normal, normal,
                {radius * longitude * 2.0f, radius * (latitude + 0.5f * glm::pi<float>()) * 2.0f});
    }
  }
  // Rows run from the north pole down, so the cells' order is reversed to face outward.
  addGridTriangles(first, uint32_t(segments + 1), segments, rings, true);
}

SceneMesh MeshBuilder::take() {
  SceneMesh mesh = std::move(mesh_);
  mesh_ = SceneMesh{};
  mesh_.material = mesh.material;
  return mesh;
}

}  // namespace triwalk
