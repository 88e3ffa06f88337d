#include "render/capture/cube_face_culling.h"

#include "core/support/errors.h"
#include "core/support/float_lanes.h"

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

void cubeFaceOutcodes(std::span<const glm::vec3> positions, glm::vec3 eye, std::span<uint32_t> codes) {
  TRIWALK_CHECK(codes.size() == positions.size(), "one code per position");
  // Face f's five bits, as in cubeFaceOutcode: d the distance along its
  // axis, j and k the other two coordinates.
  const auto face = [](Floats4 d, Floats4 j, Floats4 k, int f) {
    const int32_t bit = 1 << (5 * f);
    const Floats4 zero = splat(0.0f);
    return ((j > d) & bit) | ((-j > d) & (bit << 1)) | ((k > d) & (bit << 2)) | ((-k > d) & (bit << 3)) |
           ((d < zero) & (bit << 4));
  };
  size_t i = 0;
  for (; i + 4 <= positions.size(); i += 4) {
    const glm::vec3* p = positions.data() + i;
    const Floats4 x = Floats4{p[0].x, p[1].x, p[2].x, p[3].x} - eye.x;
    const Floats4 y = Floats4{p[0].y, p[1].y, p[2].y, p[3].y} - eye.y;
    const Floats4 z = Floats4{p[0].z, p[1].z, p[2].z, p[3].z} - eye.z;
    const Masks4 code = face(x, y, z, 0) | face(-x, y, z, 1) | face(y, z, x, 2) | face(-y, z, x, 3) | face(z, x, y, 4) |
                        face(-z, x, y, 5);
    for (int lane = 0; lane < 4; ++lane) codes[i + size_t(lane)] = uint32_t(code[lane]);
  }
  for (; i < positions.size(); ++i) codes[i] = cubeFaceOutcode(positions[i] - eye);
}

}  // namespace triwalk
