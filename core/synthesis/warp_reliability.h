#pragma once
// How much a warped pixel can be trusted (docs/DESIGN.md, "Blend weights"):
// the blend's softer seams. A source sampled a surface patch of area dA
// over the solid angle dA cos(theta_s) / |P - S|^2; the destination sees
// it over dA cos(theta_d) / |P - D|^2. Their ratio
//
//   rho = (cos theta_s / |P - S|^2) / (cos theta_d / |P - D|^2)
//
// is how many of the source's pixels land in one of the destination's (per
// unit of solid angle). Below 1 the source's samples are stretched: seen
// more obliquely by the source than by the destination (the fringes of
// depth discontinuities that pass the stretch test, grazing floors), or
// from farther away. The reliability min(1, rho), floored at
// kMinimumReliability, multiplies the paper's inverse-distance weight, so a
// stretched layer gives way to one that saw the surface well, and one
// reference takes over from another gradually rather than at a line.
// Points at infinity (sky) and splatted points (no triangle) count 1.
//
// The GPU layer pass computes the same quantity per fragment
// (shaders/warp_layer.frag), with the triangle's normal from the
// derivatives of its world position.

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace triwalk {

// Keeps every covered pixel's weight positive (the blend divides by the sum).
inline constexpr float kMinimumReliability = 1.0f / 1024.0f;

// point: the surface point; normal: its triangle's normal (any length; zero
// for a point); source, destination: the two centres.
inline float warpReliability(glm::vec3 point, glm::vec3 normal, glm::vec3 source, glm::vec3 destination) {
  const glm::vec3 fromSource = point - source, fromDestination = point - destination;
  const float sourceFacing = std::abs(glm::dot(normal, fromSource));
  const float destinationFacing = std::abs(glm::dot(normal, fromDestination));
  if (!(destinationFacing > 0.0f)) return 1.0f;  // no normal, or seen edge-on by the destination
  const float sourceDistance = glm::length(fromSource), destinationDistance = glm::length(fromDestination);
  // rho with the normal's length cancelling: (|n.(P-S)| |P-D|^3) / (|n.(P-D)| |P-S|^3).
  const float ratio = destinationDistance / sourceDistance;
  const float rho = sourceFacing / destinationFacing * ratio * ratio * ratio;
  return rho > kMinimumReliability ? std::min(rho, 1.0f) : kMinimumReliability;
}

// The reliability of a pixel drawn from a source's silhouette fringe
// (core/synthesis/silhouette_fringe.h): `fringe` is the fringe flags of the
// source pixels interpolated at the drawn point, so above 0 wherever a
// fringe pixel's colour reaches it (the triangles around a fringe vertex,
// a texel's bilinear footprint). The fringe's colour is partly another
// surface's, so there the layer counts least and one that saw the surface
// cleanly takes over; scaled by the flag instead, the half of each such
// triangle nearer the fringe pixel left the strand at half strength.
inline float fringeReliability(float reliability, float fringe) {
  return fringe > 0.0f ? kMinimumReliability : reliability;
}

}  // namespace triwalk
