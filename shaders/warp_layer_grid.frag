#version 450 core
// A grid reference's layer (warp_layer.glsl): colours interpolated between
// its pixels, as the CPU reference's grid mesh. A program of its own, so
// that a simplified reference's layer interpolates no colour.
#include "warp_layer.glsl"
in vec3 vertexColor;
in float vertexFringe;

void main() { writeLayer(vertexColor, vertexFringe); }
