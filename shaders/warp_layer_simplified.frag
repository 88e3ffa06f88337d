#version 450 core
// A simplified reference's layer (warp_layer.glsl): each pixel's colour is
// looked up along the source ray in the colour texture, as the CPU warp of
// a simplified mesh does, and its silhouette fringe flag with it.
#include "projection.glsl"
#include "warp_layer.glsl"
uniform sampler2D colorTexture;  // bilinear, wrapping in longitude
uniform ivec2 panoramaSize;
uniform float panoramaYaw;

void main() {
  vec2 size = vec2(panoramaSize);
  vec2 imagePoint = equirectImagePoint(finite > 0.0 ? worldPoint - sourcePosition : worldPoint, size, panoramaYaw);
  // Alpha: 1 - the silhouette fringe flag, interpolated as the colour is.
  vec4 texel = textureLod(colorTexture, imagePoint / size, 0.0);
  writeLayer(texel.rgb, 1.0 - texel.a);
}
