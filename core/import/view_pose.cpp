#include "core/import/view_pose.h"

#include "core/support/errors.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace triwalk {

namespace {

// The rotation that turns the source's up axis onto +z (about x, so x stays).
glm::dmat3 upRotation(UpAxis up) {
  switch (up) {
    case UpAxis::PlusZ: return glm::dmat3(1.0);
    // Columns are the images of x, y, z: y -> z, z -> -y.
    case UpAxis::PlusY: return glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
    // -y -> z: y -> -z, z -> y.
    case UpAxis::MinusY: return glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
    case UpAxis::MinusZ: return glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, -1));
  }
  return glm::dmat3(1.0);
}

bool finite(const glm::dmat4& matrix) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(matrix[c][r])) return false;
    }
  }
  return true;
}

}  // namespace

UpAxis parseUpAxis(const std::string& text, const std::string& option) {
  if (text == "z") return UpAxis::PlusZ;
  if (text == "y") return UpAxis::PlusY;
  if (text == "-y") return UpAxis::MinusY;
  if (text == "-z") return UpAxis::MinusZ;
  throw InputError(option, "unknown up axis '" + text + "' (z, y, -y or -z)");
}

const char* upAxisName(UpAxis up) {
  switch (up) {
    case UpAxis::PlusZ: return "z";
    case UpAxis::PlusY: return "y";
    case UpAxis::MinusY: return "-y";
    case UpAxis::MinusZ: return "-z";
  }
  return "z";
}

PoseMatrix parsePoseMatrix(const std::string& text, const std::string& option) {
  if (text == "camera-to-world") return PoseMatrix::CameraToWorld;
  if (text == "world-to-camera") return PoseMatrix::WorldToCamera;
  throw InputError(option, "unknown matrix kind '" + text + "' (camera-to-world or world-to-camera)");
}

const char* poseMatrixName(PoseMatrix kind) {
  return kind == PoseMatrix::CameraToWorld ? "camera-to-world" : "world-to-camera";
}

ViewPose poseFromMatrix(const glm::dmat4& matrix, PoseMatrix kind, const std::string& subject) {
  if (!finite(matrix)) throw InputError(subject, "pose matrix has a non-finite entry");
  if (matrix[0][3] != 0.0 || matrix[1][3] != 0.0 || matrix[2][3] != 0.0 || matrix[3][3] != 1.0) {
    throw InputError(subject, "pose matrix's last row is not 0 0 0 1");
  }
  const glm::dmat3 rotation(matrix);
  const glm::dmat3 error = glm::transpose(rotation) * rotation - glm::dmat3(1.0);
  double largest = 0.0;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(error[c][r]));
  }
  if (largest > 1e-3 || glm::determinant(rotation) < 0.0) {
    throw InputError(subject, "pose matrix is not a rotation and a translation (scaled, sheared or mirrored)");
  }
  const glm::dvec3 translation(matrix[3]);
  if (kind == PoseMatrix::CameraToWorld) return {translation, rotation};
  // x_cam = R x_world + t  =>  camera at -R^T t, camera-to-world R^T.
  return {-(glm::transpose(rotation) * translation), glm::transpose(rotation)};
}

ViewPose poseFromYaw(glm::dvec3 position, double yawDegrees, UpAxis up) {
  const double yaw = yawDegrees * std::numbers::pi / 180.0;
  const glm::dmat3 aboutZ(glm::dvec3(std::cos(yaw), std::sin(yaw), 0), glm::dvec3(-std::sin(yaw), std::cos(yaw), 0),
                          glm::dvec3(0, 0, 1));
  const glm::dmat3 turn = upRotation(up);
  return {position, glm::transpose(turn) * aboutZ * turn};
}

ViewPose toTriwalkFrame(const ViewPose& pose, UpAxis up, double metresPerUnit) {
  const glm::dmat3 turn = upRotation(up);
  return {turn * pose.position * metresPerUnit, turn * pose.rotation * glm::transpose(turn)};
}

double tiltRadians(const ViewPose& pose) {
  return std::acos(std::clamp(pose.rotation[2].z, -1.0, 1.0));
}

double yawDegrees(const ViewPose& pose) {
  glm::dvec2 forward(pose.rotation[0].x, pose.rotation[0].y);
  if (glm::length(forward) < 1e-9) forward = -glm::dvec2(pose.rotation[2].x, pose.rotation[2].y) * pose.rotation[0].z;
  return std::atan2(forward.y, forward.x) * 180.0 / std::numbers::pi;
}

glm::dmat4 poseMatrix(const ViewPose& pose) {
  glm::dmat4 matrix(pose.rotation);
  matrix[3] = glm::dvec4(pose.position, 1.0);
  return matrix;
}

}  // namespace triwalk
