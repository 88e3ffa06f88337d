#pragma once
// The one definition of the camera models, used by capture, the CPU warp,
// the error and the GPU path (shaders/projection.glsl mirrors it exactly).
//
// World: right-handed, metres, z up.
// Equirectangular panorama, W = 2H, continuous image coordinates: pixel
// (u, v) covers [u, u+1) x [v, v+1), its centre is (u + 0.5, v + 0.5).
//   longitude  theta = 2 pi x / W - pi + yaw     (yaw in radians, about +z)
//   latitude   phi   = pi / 2 - pi y / H
//   direction  (cos phi cos theta, cos phi sin theta, sin phi)
// Pinhole: yaw about +z measured from +x, pitch up from the horizon;
// image rows go down, pixel centres at +0.5 like the panorama.

#include "core/geometry/float_arc_tangent.h"

#include <glm/glm.hpp>

#include <cmath>
#include <numbers>
#include <span>

namespace triwalk {

constexpr float kPi = std::numbers::pi_v<float>;

inline float degreesToRadians(float degrees) { return degrees * kPi / 180.0f; }

struct EquirectProjection {
  int width = 0;
  int height = 0;
  float yaw = 0.0f;  // radians; rotation of the panorama about +z

  glm::vec3 direction(glm::vec2 imagePoint) const {
    const float theta = 2.0f * kPi * imagePoint.x / float(width) - kPi + yaw;
    const float phi = 0.5f * kPi - kPi * imagePoint.y / float(height);
    const float cosPhi = std::cos(phi);
    return {cosPhi * std::cos(theta), cosPhi * std::sin(theta), std::sin(phi)};
  }

  glm::vec3 pixelDirection(int u, int v) const { return direction({float(u) + 0.5f, float(v) + 0.5f}); }

  // Inverse of direction(); x in [0, W), y in [0, H]. The direction need not be unit.
  // The arc tangents are core/geometry/float_arc_tangent.h's: the same bits on any C library.
  glm::vec2 imagePoint(glm::vec3 direction) const {
    float theta = atan2Float(direction.y, direction.x) - yaw;
    const float phi = atan2Float(direction.z, hypotFloat(direction.x, direction.y));
    float x = (theta + kPi) * float(width) / (2.0f * kPi);
    x = std::fmod(x, float(width));
    if (x < 0.0f) x += float(width);
    if (x >= float(width)) x = 0.0f;  // fmod can round up to exactly W
    return {x, (0.5f * kPi - phi) * float(height) / kPi};
  }

  // imagePoint of each direction, the same bits, four at a time (about four
  // times faster: the CPU warp projects every pixel it colours).
  void imagePoints(std::span<const glm::vec3> directions, std::span<glm::vec2> points) const;

  // Solid angle of a pixel in row v relative to one at the equator (cos latitude).
  float rowSolidAngleWeight(int v) const {
    return std::cos(0.5f * kPi - kPi * (float(v) + 0.5f) / float(height));
  }

  int pixelCount() const { return width * height; }
};

struct PinholeCamera {
  int width = 1280;
  int height = 720;
  float verticalFovDegrees = 60.0f;
  glm::vec3 position{0.0f};
  float yawDegrees = 0.0f;
  float pitchDegrees = 0.0f;

  bool operator==(const PinholeCamera&) const = default;

  glm::vec3 forward() const {
    const float yaw = degreesToRadians(yawDegrees);
    const float pitch = degreesToRadians(pitchDegrees);
    return {std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)};
  }
  glm::vec3 right() const {
    const float yaw = degreesToRadians(yawDegrees);
    return {std::sin(yaw), -std::cos(yaw), 0.0f};
  }
  glm::vec3 up() const { return glm::cross(right(), forward()); }

  float tanHalfFovY() const { return std::tan(0.5f * degreesToRadians(verticalFovDegrees)); }
  float aspect() const { return float(width) / float(height); }

  // Camera-frame coordinates of a homogeneous world point (w = 0 for a
  // direction at infinity): x right, y up, z = depth along forward.
  glm::vec3 toCameraFrame(glm::vec4 world) const {
    const glm::vec3 relative = glm::vec3(world) - position * world.w;
    return {glm::dot(relative, right()), glm::dot(relative, up()), glm::dot(relative, forward())};
  }

  // Continuous image point of a camera-frame point with positive depth.
  glm::vec2 imagePoint(glm::vec3 cameraFrame) const {
    const float tanY = tanHalfFovY();
    const float tanX = tanY * aspect();
    return {(cameraFrame.x / (cameraFrame.z * tanX) + 1.0f) * 0.5f * float(width),
            (1.0f - cameraFrame.y / (cameraFrame.z * tanY)) * 0.5f * float(height)};
  }

  // World direction of the ray through a continuous image point.
  glm::vec3 rayDirection(glm::vec2 imagePoint) const {
    const float tanY = tanHalfFovY();
    const float tanX = tanY * aspect();
    const float x = (2.0f * imagePoint.x / float(width) - 1.0f) * tanX;
    const float y = (1.0f - 2.0f * imagePoint.y / float(height)) * tanY;
    return glm::normalize(forward() + x * right() + y * up());
  }
};

// World -> clip for a pinhole camera, reversed depth (1 at the near plane,
// 0 at infinity) with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), as the
// GPU warp and the truth frames draw.
glm::mat4 pinholeViewProjection(const PinholeCamera& camera, float near);

}  // namespace triwalk
