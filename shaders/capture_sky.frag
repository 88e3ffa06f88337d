#version 450 core
// Background of a cube face: the sky, no surface (plane 0, distance +inf).
#include "projection.glsl"
#include "sky.glsl"
in vec2 texCoord;
uniform mat4 inverseViewProjection;  // clip -> camera-relative world
layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outPlane;
layout(location = 2) out float outDistance;
void main() {
  vec4 far = inverseViewProjection * vec4(texCoord * 2.0 - 1.0, 0.5, 1.0);
  outColor = vec4(skyColor(far.xyz / far.w), 1.0);
  outPlane = vec4(0.0);
  outDistance = positiveInfinity();
}
