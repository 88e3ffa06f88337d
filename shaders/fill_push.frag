#version 450 core
// Push step of the hole fill: a coarser level from the 2x2 children of the
// finer one, only those on the farthest surface (core/synthesis/hole_fill.h).
#include "projection.glsl"
#include "hole_fill.glsl"
uniform sampler2D finer;
uniform float epsilon;
out vec4 outValue;

// A child past the finer level's edge (odd sizes) counts as unknown.
vec4 child(ivec2 texel, ivec2 fineSize) {
  if (texel.x >= fineSize.x || texel.y >= fineSize.y) return vec4(0.0, 0.0, 0.0, -1.0);
  return texelFetch(finer, topDown(texel, fineSize), 0);
}

void main() {
  ivec2 fineSize = textureSize(finer, 0);
  ivec2 coarseSize = (fineSize + 1) / 2;
  ivec2 first = 2 * topDown(ivec2(gl_FragCoord.xy), coarseSize);
  outValue = farthestSurfaceMeanOfMajority(child(first, fineSize), child(first + ivec2(1, 0), fineSize), child(first + ivec2(0, 1), fineSize),
                                           child(first + ivec2(1, 1), fineSize), vec4(1.0), epsilon);
}
