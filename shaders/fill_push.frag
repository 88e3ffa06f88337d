#version 450 core
// Push step of the hole fill: a coarser level from the 2x2 children of the
// finer one, only those on the farthest surface (core/synthesis/hole_fill.h).
#include "projection.glsl"
#include "hole_fill.glsl"
uniform sampler2D finer;
uniform float epsilon;
out vec4 outValue;

void main() {
  ivec2 fineSize = textureSize(finer, 0);
  ivec2 coarseSize = (fineSize + 1) / 2;
  ivec2 texel = topDown(ivec2(gl_FragCoord.xy), coarseSize);
  vec4 children[4];
  float weights[4] = float[4](1.0, 1.0, 1.0, 1.0);
  int count = 0;
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      ivec2 child = 2 * texel + ivec2(dx, dy);
      if (child.x < fineSize.x && child.y < fineSize.y) children[count++] = texelFetch(finer, topDown(child, fineSize), 0);
    }
  }
  outValue = farthestSurfaceMean(children, weights, count, epsilon);
}
