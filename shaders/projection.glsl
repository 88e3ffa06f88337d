// Mirror of core/geometry/projection.h (EquirectProjection): keep the two identical.
const float kPi = 3.14159265358979323846;

// Continuous image point (x, y) of a W x H panorama -> unit world direction.
vec3 equirectDirection(vec2 imagePoint, vec2 size, float yaw) {
  float theta = 2.0 * kPi * imagePoint.x / size.x - kPi + yaw;
  float phi = 0.5 * kPi - kPi * imagePoint.y / size.y;
  return vec3(cos(phi) * cos(theta), cos(phi) * sin(theta), sin(phi));
}

// World direction -> continuous image point (x in [0, W) up to rounding).
vec2 equirectImagePoint(vec3 direction, vec2 size, float yaw) {
  float theta = atan(direction.y, direction.x) - yaw;
  float phi = atan(direction.z, length(direction.xy));
  return vec2(fract((theta + kPi) / (2.0 * kPi)) * size.x, (0.5 * kPi - phi) * size.y / kPi);
}

float positiveInfinity() { return uintBitsToFloat(0x7F800000u); }
