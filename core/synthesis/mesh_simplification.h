#pragma once
// Bounded simplification of a source panorama's triangles for the warp
// (docs/DESIGN.md, "Simplified source meshes"), by meshoptimizer's
// edge-collapse simplifier: most of a panorama is planar walls, floor and
// ceiling, whose two triangles per pixel quad collapse to a few large ones
// at no geometric error.

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace triwalk {

// Simplifies an indexed triangle list (three vertex indices per triangle)
// until the next collapse would move the surface by more than
// `absoluteError` (in the positions' units). Borders (where the stretch
// test dropped triangles) only slide along themselves, so holes keep their
// shape. Returns indices into the same vertex array; deterministic.
std::vector<uint32_t> simplifyTriangles(std::span<const uint32_t> indices, std::span<const glm::vec3> positions,
                                        float absoluteError);

}  // namespace triwalk
