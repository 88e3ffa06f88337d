#include "render/capture/cube_face_culling.h"

namespace triwalk {

uint32_t cubeFaceOutcode(glm::vec3 relative) {
  uint32_t code = 0;
  for (int face = 0; face < kCubeFaces; ++face) {
    const int axis = face / 2;
    // Distance along the face's axis: the cone is |p_j| <= d and |p_k| <= d.
    const float d = face % 2 == 0 ? relative[axis] : -relative[axis];
    const float pj = relative[(axis + 1) % 3], pk = relative[(axis + 2) % 3];
    const uint32_t beyond = uint32_t(pj > d) | uint32_t(-pj > d) << 1 | uint32_t(pk > d) << 2 | uint32_t(-pk > d) << 3 |
                            uint32_t(d < 0.0f) << 4;
    code |= beyond << (5 * face);
  }
  return code;
}

}  // namespace triwalk
