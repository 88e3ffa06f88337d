// The hole fill's shared steps (core/synthesis/hole_fill.h, docs/DESIGN.md,
// "Hole filling"); texels hold linear rgb and the inverse distance in a
// (0 for sky, negative where nothing is known). Pyramid levels are indexed
// from the top row, as the CPU reference does, so odd sizes pair the same
// rows on both.

ivec2 topDown(ivec2 texel, ivec2 size) { return ivec2(texel.x, size.y - 1 - texel.y); }

// The weighted mean of the known candidates on the farthest surface
// (inverse distance within (1 + epsilon) of the smallest); unknown if none.
vec4 farthestSurfaceMean(vec4 candidates[4], float weights[4], int count, float epsilon) {
  float nearestInverse = positiveInfinity();
  for (int i = 0; i < count; ++i) {
    if (candidates[i].a >= 0.0) nearestInverse = min(nearestInverse, candidates[i].a);
  }
  if (isinf(nearestInverse)) return vec4(0.0, 0.0, 0.0, -1.0);
  float limit = nearestInverse * (1.0 + epsilon);
  vec4 sum = vec4(0.0);
  float weightSum = 0.0;
  for (int i = 0; i < count; ++i) {
    if (candidates[i].a < 0.0 || candidates[i].a > limit) continue;
    sum += weights[i] * candidates[i];
    weightSum += weights[i];
  }
  return sum / weightSum;
}
