#pragma once
// Imported panoramas to triwalk's convention and orientation.
//
// Panorama photos and the layouts triwalk imports put the view to the
// camera's right on the right of the picture (longitude grows clockwise
// seen from above). triwalk's equirectangular projection
// (core/geometry/projection.h) grows counter-clockwise, like a map, so a
// photo's column u is triwalk's column W - 1 - u: an exact permutation,
// undone on export.
//
// triwalk's views turn only about z. A tilted camera's panorama is
// resampled onto an upright one: each upright pixel's ray is turned into
// the camera's frame and looked up there (colour bilinear, distance from
// the nearest pixel, so depth edges stay sharp).

#include "core/image/image.h"

#include <glm/glm.hpp>

namespace triwalk {

template <typename Pixel>
void mirrorColumns(Image<Pixel>& image) {
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width / 2; ++x) std::swap(image.at(x, y), image.at(image.width - 1 - x, y));
  }
}

// The panorama seen by a camera turned by cameraToWorld (z up), resampled
// for an upright camera with the given yaw (radians).
Panorama uprightPanorama(const Panorama& cameraPanorama, const glm::dmat3& cameraToWorld, float yaw);

// The largest tilt (radians) left unresampled: a quarter of a pixel's
// angle, far below what warping at that resolution can show.
double negligibleTiltRadians(int panoramaWidth);

}  // namespace triwalk
