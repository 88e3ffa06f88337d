// The hole fill's shared steps (core/synthesis/hole_fill.h, docs/DESIGN.md,
// "Hole filling"); texels hold linear rgb and the inverse distance in a
// (0 for sky, negative where nothing is known). Pyramid levels are indexed
// from the top row, as the CPU reference does, so odd sizes pair the same
// rows on both.

ivec2 topDown(ivec2 texel, ivec2 size) { return ivec2(texel.x, size.y - 1 - texel.y); }

// The weighted mean of the known candidates on the farthest surface
// (inverse distance within (1 + epsilon) of the smallest); unknown if none.
// The four candidates are held as vector lanes, not an array indexed in a
// loop: no per-candidate branches for llvmpipe's eight pixels in lockstep.
vec4 farthestSurfaceMean(vec4 c0, vec4 c1, vec4 c2, vec4 c3, vec4 weights, float epsilon) {
  vec4 inverse = vec4(c0.a, c1.a, c2.a, c3.a);
  bvec4 known = greaterThanEqual(inverse, vec4(0.0));
  vec4 knownInverse = mix(vec4(positiveInfinity()), inverse, known);
  float nearestInverse = min(min(knownInverse.x, knownInverse.y), min(knownInverse.z, knownInverse.w));
  if (isinf(nearestInverse)) return vec4(0.0, 0.0, 0.0, -1.0);
  vec4 w = weights * vec4(lessThanEqual(knownInverse, vec4(nearestInverse * (1.0 + epsilon))));
  return (w.x * c0 + w.y * c1 + w.z * c2 + w.w * c3) / (w.x + w.y + w.z + w.w);
}

// The push's candidates with sky dropped where surfaces outnumber it
// (weights summed): sky (q = 0) is farther than any surface, so without this
// one sky child makes the whole coarser texel sky, and sky seen through a
// small opening spreads over every coarser level and into holes on the wall
// around it.
vec4 outvotedSkyDropped(vec4 candidate, bool drop) {
  return drop && candidate.a == 0.0 ? vec4(0.0, 0.0, 0.0, -1.0) : candidate;
}

vec4 farthestSurfaceMeanOfMajority(vec4 c0, vec4 c1, vec4 c2, vec4 c3, vec4 weights, float epsilon) {
  vec4 inverse = vec4(c0.a, c1.a, c2.a, c3.a);
  float sky = dot(weights, vec4(equal(inverse, vec4(0.0))));
  float surface = dot(weights, vec4(greaterThan(inverse, vec4(0.0))));
  bool drop = surface > sky;
  return farthestSurfaceMean(outvotedSkyDropped(c0, drop), outvotedSkyDropped(c1, drop), outvotedSkyDropped(c2, drop),
                             outvotedSkyDropped(c3, drop), weights, epsilon);
}
