#version 450 core
// Pull step of the hole fill: a texel nothing is known at takes the
// bilinear interpolation of its four nearest coarser texels, only those on
// the farthest surface (core/synthesis/hole_fill.h); known texels stay.
// At the frame's level the pass runs on its holes only (a depth test
// against the resolve's hole mark) and also writes their display colour.
#include "projection.glsl"
#include "display.glsl"
#include "hole_fill.glsl"
uniform sampler2D level;    // this level's pushed values
uniform sampler2D coarser;  // the coarser level, already filled
uniform float epsilon;
layout(location = 0) out vec4 outValue;
layout(location = 1) out vec4 outColor;  // the frame's level only: black if nothing at all is known

// A coarser texel, clamped to the level (its edge texels stand in for the
// ones past it).
vec4 parent(ivec2 texel, ivec2 coarseSize) {
  return texelFetch(coarser, topDown(clamp(texel, ivec2(0), coarseSize - 1), coarseSize), 0);
}

void main() {
  ivec2 size = textureSize(level, 0);
  ivec2 coarseSize = textureSize(coarser, 0);
  ivec2 texel = topDown(ivec2(gl_FragCoord.xy), size);
  vec4 own = texelFetch(level, topDown(texel, size), 0);
  if (own.a >= 0.0) {
    outValue = own;
    outColor = displayColor(own.rgb);
    return;
  }
  // The texel centre in coarser coordinates is (x + 0.5) / 2 - 0.5: the
  // nearer coarser texel weighs 3/4 along each axis.
  ivec2 base = ivec2(texel.x % 2 == 0 ? texel.x / 2 - 1 : texel.x / 2, texel.y % 2 == 0 ? texel.y / 2 - 1 : texel.y / 2);
  vec2 f = vec2(texel.x % 2 == 0 ? 0.75 : 0.25, texel.y % 2 == 0 ? 0.75 : 0.25);
  vec4 weights = vec4((1.0 - f.x) * (1.0 - f.y), f.x * (1.0 - f.y), (1.0 - f.x) * f.y, f.x * f.y);
  outValue = farthestSurfaceMean(parent(base, coarseSize), parent(base + ivec2(1, 0), coarseSize),
                                 parent(base + ivec2(0, 1), coarseSize), parent(base + ivec2(1, 1), coarseSize), weights,
                                 epsilon);
  outColor = outValue.a < 0.0 ? vec4(0.0, 0.0, 0.0, 1.0) : displayColor(outValue.rgb);
}
