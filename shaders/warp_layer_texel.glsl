// A warp layer's texel (RGBA32UI): colour as three halves, the layer's
// reliability as a half, and 1 / distance as a float (-1: uncovered,
// 0: sky).
uvec4 warpLayerTexel(vec3 color, float inverseDistance, float reliability) {
  return uvec4(packHalf2x16(color.rg), packHalf2x16(vec2(color.b, reliability)), floatBitsToUint(inverseDistance), 0u);
}

struct WarpLayerValue {
  vec3 color;
  float inverseDistance;
  float reliability;
};

WarpLayerValue warpLayerValue(uvec4 texel) {
  vec2 bAndReliability = unpackHalf2x16(texel.y);
  return WarpLayerValue(vec3(unpackHalf2x16(texel.x), bAndReliability.x), uintBitsToFloat(texel.z), bAndReliability.y);
}
