#version 450 core
// Blend of the reference layers (paper Eq. 1-2, made relative; the same
// rule as core/synthesis/blend.cpp): z_front is the nearest distance over layers,
// layers within epsilon * z_front of it average with weights
// 1 / max(dist(D, S_k), r_min); pixels no layer covers are holes.
// Writes display (sRGB-encoded) color.
#include "projection.glsl"
uniform sampler2D layer0;
uniform sampler2D layer1;
uniform sampler2D layer2;
uniform int layerCount;
uniform vec3 weights;
uniform float epsilon;
uniform vec3 holeColor;     // display color of holes
uniform bool showSources;   // color by the references that contributed
out vec4 outColor;

float linearToSrgb(float linear) {
  float c = clamp(linear, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 values[3] = vec4[3](texelFetch(layer0, pixel, 0), texelFetch(layer1, pixel, 0), texelFetch(layer2, pixel, 0));
  float front = positiveInfinity();
  bool covered = false;
  for (int k = 0; k < layerCount; ++k) {
    if (values[k].a < 0.0) continue;
    covered = true;
    front = min(front, values[k].a > 0.0 ? 1.0 / values[k].a : positiveInfinity());
  }
  if (!covered) {
    outColor = vec4(holeColor, 1.0);
    return;
  }
  vec3 sum = vec3(0.0);
  vec3 sources = vec3(0.0);
  float weightSum = 0.0;
  for (int k = 0; k < layerCount; ++k) {
    if (values[k].a < 0.0) continue;
    float d = values[k].a > 0.0 ? 1.0 / values[k].a : positiveInfinity();
    bool inInterval = isinf(front) ? isinf(d) : abs(d - front) < epsilon * front;
    if (!inInterval) continue;
    sum += weights[k] * values[k].rgb;
    weightSum += weights[k];
    sources[k] = 1.0;
  }
  if (showSources) {
    outColor = vec4(sources, 1.0);
    return;
  }
  vec3 color = sum / weightSum;
  outColor = vec4(linearToSrgb(color.r), linearToSrgb(color.g), linearToSrgb(color.b), 1.0);
}
