#pragma once
// Depth maps of imported captures to triwalk's distance: metres along each
// pixel's ray from the panorama centre, +inf where there is no depth.

#include "core/image/image.h"

#include <filesystem>
#include <string>

namespace triwalk {

// What the stored depth measures, for a pixel whose unit ray in the
// camera frame is (x, y, z) (z up) and whose surface point is at distance d:
//   Euclidean:  d, along the ray (the default; RealSee3D, Pano3D)
//   CubeZ:      d * max(|x|, |y|, |z|), the z-buffer depth of the 90-degree
//               cube face the ray passes through (renderers that stitch six
//               perspective views)
//   Horizontal: d * hypot(x, y), the distance from the vertical axis
//               through the centre (cylindrical renderers)
enum class DepthKind { Euclidean, CubeZ, Horizontal };
DepthKind parseDepthKind(const std::string& text, const std::string& option);
const char* depthKindName(DepthKind kind);

// A depth file and its scale: metres = stored value / unitsPerMetre. The
// encoding follows the extension: .exr is one float channel, .png a
// 16-bit grey image.
struct DepthFile {
  std::filesystem::path path;
  double unitsPerMetre = 1.0;
};

struct DecodedDepth {
  ScalarImage metres;      // stored value / scale; +inf where invalid
  size_t invalidPixels = 0;  // stored 0 or +inf
};

// Reads a depth file as stored (columns in the file's order).
DecodedDepth decodeDepthFile(const DepthFile& file);

// Turns depth of the given kind, in triwalk's column order and camera
// frame (yaw 0), into distance along each ray, in place.
void convertToDistance(ScalarImage& depth, DepthKind kind);

// The stored value of a distance (inverse of convertToDistance for one pixel).
float depthOfKind(float distance, glm::vec3 cameraRay, DepthKind kind);

}  // namespace triwalk
