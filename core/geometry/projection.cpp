#include "core/geometry/projection.h"

namespace triwalk {

void EquirectProjection::imagePoints(std::span<const glm::vec3> directions, std::span<glm::vec2> points) const {
  const float w = float(width), h = float(height);
  size_t i = 0;
  for (; i + 4 <= directions.size(); i += 4) {
    const Floats4 x = {directions[i].x, directions[i + 1].x, directions[i + 2].x, directions[i + 3].x};
    const Floats4 y = {directions[i].y, directions[i + 1].y, directions[i + 2].y, directions[i + 3].y};
    const Floats4 z = {directions[i].z, directions[i + 1].z, directions[i + 2].z, directions[i + 3].z};
    Masks4 unhandled = {0, 0, 0, 0};
    const Floats4 theta = atan2Floats(y, x, unhandled) - yaw;
    // x and y are finite in the lanes left (the first arc tangent sets the others).
    const Floats4 phi = atan2Floats(z, hypotFloats(x, y), unhandled);
    Floats4 column = (theta + kPi) * w / (2.0f * kPi);
    // fmod(column, W) is column itself within (-W, W) and column - W (exact)
    // within [W, 2W); anything else goes to imagePoint.
    unhandled |= ((column > -w) & (column < 2.0f * w)) == 0;
    column = column >= w ? column - w : column;
    column = column < 0.0f ? column + w : column;
    column = column >= w ? Floats4{} : column;
    const Floats4 row = (0.5f * kPi - phi) * h / kPi;
    for (int lane = 0; lane < 4; ++lane) {
      points[i + size_t(lane)] = unhandled[lane] ? imagePoint(directions[i + size_t(lane)]) : glm::vec2(column[lane], row[lane]);
    }
  }
  for (; i < directions.size(); ++i) points[i] = imagePoint(directions[i]);
}

glm::mat4 pinholeViewProjection(const PinholeCamera& camera, float near) {
  const glm::vec3 r = camera.right(), u = camera.up(), f = camera.forward(), c = camera.position;
  glm::mat4 view(1.0f);  // camera looks down -z, as OpenGL expects
  view[0] = glm::vec4(r.x, u.x, -f.x, 0.0f);
  view[1] = glm::vec4(r.y, u.y, -f.y, 0.0f);
  view[2] = glm::vec4(r.z, u.z, -f.z, 0.0f);
  view[3] = glm::vec4(-glm::dot(r, c), -glm::dot(u, c), glm::dot(f, c), 1.0f);
  const float tanY = camera.tanHalfFovY();
  glm::mat4 projection(0.0f);
  projection[0][0] = 1.0f / (tanY * camera.aspect());
  projection[1][1] = 1.0f / tanY;
  projection[2][3] = -1.0f;
  projection[3][2] = near;
  return projection * view;
}

}  // namespace triwalk
