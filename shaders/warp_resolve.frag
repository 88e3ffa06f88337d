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
// pass runs on the holes alone. The holes pass (holesOnly) resolves more
// references into the holes the first pass left, tested against that mark
// (GL_LEQUAL): a pixel it covers is marked 0.5, so it passes where the mark
// is 1 and nowhere else, and the fill still finds the holes left at 1.
// The trust view (the viewer's T) colours each pixel by the sum of the
// reliabilities of the layers within the blend interval, over 3: 1 where
// all three references saw the surface well, 1/3 where one alone saw it
// head-on, lower where what saw it saw it stretched; the scene's
// brightness shades it so that the view stays legible. Holes are black.
#include "display.glsl"
#include "warp_layer_texel.glsl"
uniform usampler2D layer0;
uniform usampler2D layer1;
uniform usampler2D layer2;
uniform int layerCount;
uniform vec3 weights;
uniform bool reliabilityWeights;
uniform float epsilon;
uniform bool showSources;   // color by the references that contributed
uniform bool showTrust;     // color by how much to trust the pixel (below)
uniform vec3 holeColor;     // display colour
uniform bool holesOnly;     // the holes pass (above)
layout(location = 0) out vec4 outValue;
layout(location = 1) out vec4 outColor;

// Written over the three layers at once, without arrays indexed by a loop
// variable or branches per layer: llvmpipe runs eight pixels in lockstep,
// and this form measured 14% faster than per-layer loops (docs/BENCHMARKS.md). The interval
// test is made on inverse distances a (layer) and A (the nearest):
// d - z_front < epsilon * z_front is a * (1 + epsilon) > A.
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  WarpLayerValue value0 = warpLayerValue(texelFetch(layer0, pixel, 0)), value1 = warpLayerValue(texelFetch(layer1, pixel, 0)),
                 value2 = warpLayerValue(texelFetch(layer2, pixel, 0));
  vec3 inverse = vec3(value0.inverseDistance, layerCount > 1 ? value1.inverseDistance : -1.0,
                      layerCount > 2 ? value2.inverseDistance : -1.0);
  float nearest = max(max(inverse.x, inverse.y), inverse.z);  // -1: no layer covers the pixel
  if (nearest < 0.0) {
    outValue = vec4(0.0, 0.0, 0.0, -1.0);
    outColor = vec4(holeColor, 1.0);
    gl_FragDepth = 1.0;
    return;
  }
  // Sky (0) blends with sky alone; a surface with the layers near it.
  vec3 inInterval = nearest > 0.0 ? vec3(greaterThan(inverse * (1.0 + epsilon), vec3(nearest)))
                                  : vec3(equal(inverse, vec3(0.0)));
  vec3 reliabilities = reliabilityWeights ? vec3(value0.reliability, value1.reliability, value2.reliability) : vec3(1.0);
  vec3 w = weights * reliabilities * inInterval;
  vec3 blended = (w.x * value0.color + w.y * value1.color + w.z * value2.color) / (w.x + w.y + w.z);
  outValue = vec4(showSources ? inInterval : blended, nearest);
  outColor = displayColor(outValue.rgb);
  if (showTrust) {
    float trust = dot(inInterval, vec3(value0.reliability, value1.reliability, value2.reliability)) / 3.0;
    float brightness = dot(outColor.rgb, vec3(0.2126, 0.7152, 0.0722));
    outColor = vec4(falseColor(trust) * (0.4 + 0.6 * brightness), 1.0);
  }
  gl_FragDepth = holesOnly ? 0.5 : 0.0;
}
