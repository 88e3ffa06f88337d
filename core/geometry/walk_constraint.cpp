#include "core/geometry/walk_constraint.h"

#include "core/geometry/walkable_region.h"

#include <cmath>

namespace triwalk {

bool isWalkable(const ViewMesh& mesh, glm::dvec2 point) {
  if (mesh.region() && !mesh.region()->empty() && mesh.region()->contains(point)) return true;
  const int t = mesh.locate(point);
  return t >= 0 && mesh.contains(t, point);
}

glm::vec3 constrainedStep(const ViewMesh& mesh, glm::vec3 from, glm::vec2 step) {
  const glm::vec2 start(from);
  for (const glm::vec2 candidate : {start + step, start + glm::vec2(step.x, 0.0f), start + glm::vec2(0.0f, step.y)}) {
    if (isWalkable(mesh, glm::dvec2(candidate))) return glm::vec3(candidate, from.z);
  }
  return from;
}

int nearestVertexAhead(const ViewMesh& mesh, glm::dvec2 from, double yawDegrees) {
  const double yaw = glm::radians(yawDegrees);
  const glm::dvec2 ahead(std::cos(yaw), std::sin(yaw));
  for (const double halfAngle : {60.0, 90.0}) {
    const double minimumCosine = std::cos(glm::radians(halfAngle)) - 1e-9;
    int best = -1;
    double bestDistance = 0.0;
    for (int v : mesh.vertices()) {
      const glm::dvec2 offset = mesh.position(v) - from;
      const double distance = glm::length(offset);
      if (distance <= 0.1 || glm::dot(offset, ahead) < minimumCosine * distance) continue;
      if (best < 0 || distance < bestDistance) best = v, bestDistance = distance;
    }
    if (best >= 0) return best;
  }
  return -1;
}

}  // namespace triwalk
