#version 450 core
// Blend of the reference layers (paper Eq. 1-2, made relative; the same
// rule as core/synthesis/blend.cpp): z_front is the nearest distance over layers,
// layers within epsilon * z_front of it average with weights
// 1 / max(dist(D, S_k), r_min), times the layer's reliability at the pixel
// unless the paper's weights alone are asked for; pixels no layer covers
// are holes.
// Writes the linear colour and the inverse distance of z_front (0 for sky,
// -1 for holes) for the hole fill, the frame's display colour (holeColor
// in holes), and depth 1 in holes, 0 elsewhere, so that the fill's last
// pass runs on the holes alone.
#include "projection.glsl"
#include "display.glsl"
uniform sampler2D layer0;
uniform sampler2D layer1;
uniform sampler2D layer2;
uniform sampler2D reliability0;
uniform sampler2D reliability1;
uniform sampler2D reliability2;
uniform int layerCount;
uniform vec3 weights;
uniform bool reliabilityWeights;
uniform float epsilon;
uniform bool showSources;   // color by the references that contributed
uniform vec3 holeColor;     // display colour
layout(location = 0) out vec4 outValue;
layout(location = 1) out vec4 outColor;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 values[3] = vec4[3](texelFetch(layer0, pixel, 0), texelFetch(layer1, pixel, 0), texelFetch(layer2, pixel, 0));
  vec3 reliabilities = reliabilityWeights ? vec3(texelFetch(reliability0, pixel, 0).r, texelFetch(reliability1, pixel, 0).r,
                                                 texelFetch(reliability2, pixel, 0).r)
                                          : vec3(1.0);
  float front = positiveInfinity();
  bool covered = false;
  for (int k = 0; k < layerCount; ++k) {
    if (values[k].a < 0.0) continue;
    covered = true;
    front = min(front, values[k].a > 0.0 ? 1.0 / values[k].a : positiveInfinity());
  }
  if (!covered) {
    outValue = vec4(0.0, 0.0, 0.0, -1.0);
    outColor = vec4(holeColor, 1.0);
    gl_FragDepth = 1.0;
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
    float weight = weights[k] * reliabilities[k];
    sum += weight * values[k].rgb;
    weightSum += weight;
    sources[k] = 1.0;
  }
  float inverseFront = isinf(front) ? 0.0 : 1.0 / front;
  outValue = vec4(showSources ? sources : sum / weightSum, inverseFront);
  outColor = displayColor(outValue.rgb);
  gl_FragDepth = 0.0;
}
