#version 450 core
// A reference's layer: its nearest surface per pixel (the depth test),
// linear color and 1 / distance (interpolated perspective-correctly, as
// the CPU reference does). Alpha -1 (the clear value) means uncovered.
// The second target is the layer's reliability at the pixel
// (core/synthesis/warp_reliability.h, the same formula): the triangle's
// normal is the cross product of the world point's screen derivatives,
// exact for a planar triangle since all four pixels of a quad evaluate the
// same triangle; a point (no triangle) has none and counts 1, as on the CPU.
#include "projection.glsl"
uniform vec3 sourcePosition;
uniform vec3 cameraPosition;
uniform bool explicitVertices;   // simplified mesh: colour along the source ray
uniform sampler2D colorTexture;  // bilinear, wrapping in longitude
uniform ivec2 panoramaSize;
uniform float panoramaYaw;
in vec3 vertexColor;
in float inverseDistance;
in vec3 worldPoint;
layout(location = 0) out vec4 layer;
layout(location = 1) out float reliability;

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

void main() {
  vec3 color = vertexColor;
  if (explicitVertices) {
    vec2 size = vec2(panoramaSize);
    vec2 imagePoint = equirectImagePoint(inverseDistance > 0.0 ? worldPoint - sourcePosition : worldPoint, size, panoramaYaw);
    color = textureLod(colorTexture, imagePoint / size, 0.0).rgb;
  }
  layer = vec4(color, inverseDistance);
  vec3 normal = cross(dFdx(worldPoint), dFdy(worldPoint));
  reliability = inverseDistance > 0.0 ? warpReliability(worldPoint, normal) : 1.0;
}
