// What every reference's layer writes (warp_layer_grid.frag,
// warp_layer_simplified.frag): its nearest surface per pixel (the depth
// test), linear colour and 1 / distance (of the world point interpolated
// perspective-correctly, as the CPU reference measures it; writeLayer),
// and the layer's reliability at the pixel
// (core/synthesis/warp_reliability.h, the same formula), packed into one
// target (warp_layer_texel.glsl): on llvmpipe a second render target costs
// more than the packing. 1 / distance -1 (the clear value) means
// uncovered. The triangle's normal is the cross product of the world
// point's screen derivatives, exact for a planar triangle since all four
// pixels of a quad evaluate the same triangle; a point (no triangle) has
// none and counts 1, as on the CPU. Pixels drawn from the source's
// silhouette fringe are trusted least (fringeReliability).
#include "warp_layer_texel.glsl"
uniform vec3 sourcePosition;
uniform vec3 cameraPosition;
in float finite;  // 1 on a surface, 0 in the sky (warp_layer.vert)
in vec3 worldPoint;
layout(location = 0) out uvec4 layer;

const float kMinimumReliability = 1.0 / 1024.0;

float warpReliability(vec3 point, vec3 normal) {
  vec3 fromSource = point - sourcePosition, fromDestination = point - cameraPosition;
  float sourceFacing = abs(dot(normal, fromSource));
  float destinationFacing = abs(dot(normal, fromDestination));
  if (!(destinationFacing > 0.0)) return 1.0;
  float ratio = length(fromDestination) / length(fromSource);
  float rho = sourceFacing / destinationFacing * ratio * ratio * ratio;
  return rho > kMinimumReliability ? min(rho, 1.0) : kMinimumReliability;
}

// core/synthesis/warp_reliability.h's fringeReliability.
float fringeReliability(float reliability, float fringe) {
  return fringe > 0.0 ? kMinimumReliability : reliability;
}

// fringe: the source's silhouette fringe flags interpolated at the pixel.
// The inverse distance written is that of the interpolated world point,
// exact on the triangle's plane; an interpolated 1 / distance is not, and
// across a simplified triangle metres wide it was off by several percent,
// more than the blend interval: a wall seen by two references counted as
// two surfaces, and the nearer-seeming one's silhouette fringe was drawn
// alone.
void writeLayer(vec3 color, float fringe) {
  vec3 normal = cross(dFdx(worldPoint), dFdy(worldPoint));
  bool surface = finite > 0.0;
  float reliability = surface ? warpReliability(worldPoint, normal) : 1.0;
  float inverseDistance = surface ? 1.0 / length(worldPoint - cameraPosition) : 0.0;
  layer = warpLayerTexel(color, inverseDistance, fringeReliability(reliability, fringe));
}
