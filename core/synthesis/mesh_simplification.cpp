#include "core/synthesis/mesh_simplification.h"

#include <meshoptimizer.h>

namespace triwalk {

std::vector<uint32_t> simplifyTriangles(std::span<const uint32_t> indices, std::span<const glm::vec3> positions,
                                        float absoluteError) {
  if (indices.empty()) return {};
  const float* coordinates = &positions[0].x;
  // meshoptimizer takes the error relative to the mesh's extent.
  const float scale = meshopt_simplifyScale(coordinates, positions.size(), sizeof(glm::vec3));
  if (!(scale > 0.0f)) return {indices.begin(), indices.end()};
  std::vector<uint32_t> simplified(indices.size());
  // Target 0 triangles: the error bound alone decides where to stop.
  const size_t count = meshopt_simplify(simplified.data(), indices.data(), indices.size(), coordinates, positions.size(),
                                        sizeof(glm::vec3), 0, absoluteError / scale, meshopt_SimplifyLockBorder, nullptr);
  simplified.resize(count);
  return simplified;
}

}  // namespace triwalk
