#version 450 core
// render/walkthrough/panorama_overlay.h: the panorama in each pixel's ray
// direction, with the overlay's opacity. right and up are scaled by the
// half field of view's tangents, so texCoord's corners are the frustum's.
#include "projection.glsl"
uniform sampler2D panorama;
uniform vec3 forward;
uniform vec3 right;
uniform vec3 up;
uniform vec2 panoramaSize;
uniform float panoramaYaw;
uniform float opacity;
in vec2 texCoord;
layout(location = 0) out vec4 outColor;
void main() {
  vec2 ndc = texCoord * 2.0 - 1.0;  // y up: the viewport's bottom row first
  vec3 direction = normalize(forward + ndc.x * right + ndc.y * up);
  vec2 imagePoint = equirectImagePoint(direction, panoramaSize, panoramaYaw);
  outColor = vec4(texture(panorama, imagePoint / panoramaSize).rgb, opacity);
}
