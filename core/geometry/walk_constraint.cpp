#include "core/geometry/walk_constraint.h"

#include "core/geometry/walkable_region.h"

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

}  // namespace triwalk
