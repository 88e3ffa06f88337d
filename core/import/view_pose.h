#pragma once
// Camera poses of imported captures, and their conversion to triwalk's
// frame (metres, z up, a panorama turned only about z).
//
// A pose is the camera-to-world rotation R and the position p in the
// source's world axes. The camera's own axes follow the same convention as
// its world: with the identity rotation the panorama's centre column looks
// along +x and its top row along the world's up axis (+z, or +y with
// --up y, ...). The source's up axis is turned onto +z by one rotation U,
// applied to the world and to the camera frame alike: p' = U p and
// R' = U R U^T.

#include <glm/glm.hpp>

#include <string>

namespace triwalk {

enum class UpAxis { PlusZ, PlusY, MinusY, MinusZ };
UpAxis parseUpAxis(const std::string& text, const std::string& option);
const char* upAxisName(UpAxis up);

// Whether a 4x4 matrix file gives the camera-to-world transform or its inverse.
enum class PoseMatrix { CameraToWorld, WorldToCamera };
PoseMatrix parsePoseMatrix(const std::string& text, const std::string& option);
const char* poseMatrixName(PoseMatrix kind);

struct ViewPose {
  glm::dvec3 position{0.0};
  glm::dmat3 rotation{1.0};  // camera to world
};

// A pose from a 4x4 matrix (column-major, as glm stores it); throws
// InputError naming subject unless it is finite, rigid (rotation within
// 1e-3 of orthonormal, determinant +1) and its last row is 0 0 0 1.
ViewPose poseFromMatrix(const glm::dmat4& matrix, PoseMatrix kind, const std::string& subject);

// A camera at position turned by yawDegrees about the source's up axis,
// counter-clockwise seen from above (the manifest's yaw_degrees).
ViewPose poseFromYaw(glm::dvec3 position, double yawDegrees, UpAxis up);

// The pose in triwalk's frame: z up, positions times metresPerUnit.
ViewPose toTriwalkFrame(const ViewPose& pose, UpAxis up, double metresPerUnit);

// The camera's tilt: the angle between its up axis and +z, radians.
double tiltRadians(const ViewPose& pose);
// The yaw of a triwalk-frame pose: the direction of its forward axis
// about +z, degrees in (-180, 180] (the camera's up axis when it looks
// straight up or down).
double yawDegrees(const ViewPose& pose);

// The 4x4 camera-to-world matrix of a pose.
glm::dmat4 poseMatrix(const ViewPose& pose);

}  // namespace triwalk
