#pragma once
// Which triangles each face of a capture's cube map can show. Face f sees
// the closed 90-degree cone around its axis (GL's face order: +X, -X, +Y,
// -Y, +Z, -Z, world axes, from the eye): the points in front of the eye
// (along the axis) within the four side planes through the eye. A triangle
// whose three vertices lie strictly beyond one of those five planes lies
// wholly outside the cone, so it covers none of the face's pixels and
// leaving it out of that face's draw changes no pixel. Every other
// triangle is kept, in the scene's order, so depth ties resolve as before.
//
// Why: on llvmpipe a small capture's time is the vertex work of drawing
// the whole scene six times (the region search's 32x16 probes: 84% of
// the CPU on the thread that shades vertices). A triangle far from the
// eye meets one or two faces, so the six draws shade about the vertices
// of one or two.

#include <glm/glm.hpp>

#include <cstdint>
#include <span>

namespace triwalk {

constexpr int kCubeFaces = 6;

// Bit 5 f + k set when a point (relative to the eye) lies strictly beyond
// plane k of face f: the four side planes, then the plane through the eye
// across the face's axis (behind the eye).
uint32_t cubeFaceOutcode(glm::vec3 relative);

// cubeFaceOutcode(positions[i] - eye) into codes[i] for every i, four
// vertices at a time in float lanes, with the same subtractions and
// comparisons lane by lane (so the same bits). A small probe of a level
// computes the code of every vertex of the level for each eye: in the
// scalar form this was the largest single part of the region search.
void cubeFaceOutcodes(std::span<const glm::vec3> positions, glm::vec3 eye, std::span<uint32_t> codes);

// Bit f set when a triangle with these vertex outcodes may show on face f.
inline uint8_t cubeFacesTouched(uint32_t a, uint32_t b, uint32_t c) {
  const uint32_t beyondTogether = a & b & c;
  uint8_t faces = 0;
  for (int face = 0; face < kCubeFaces; ++face) {
    if (((beyondTogether >> (5 * face)) & 0x1Fu) == 0) faces |= uint8_t(1u << face);
  }
  return faces;
}

}  // namespace triwalk
