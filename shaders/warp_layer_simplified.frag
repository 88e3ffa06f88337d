#version 450 core
// A simplified reference's layer (warp_layer.glsl): each pixel's colour is
// looked up along the source ray in the colour texture, as the CPU warp of
// a simplified mesh does.
#include "projection.glsl"
#include "warp_layer.glsl"
uniform sampler2D colorTexture;  // bilinear, wrapping in longitude
uniform ivec2 panoramaSize;
uniform float panoramaYaw;

void main() {
  vec2 size = vec2(panoramaSize);
  vec2 imagePoint = equirectImagePoint(inverseDistance > 0.0 ? worldPoint - sourcePosition : worldPoint, size, panoramaYaw);
  writeLayer(textureLod(colorTexture, imagePoint / size, 0.0).rgb);
}
