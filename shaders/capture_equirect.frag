#version 450 core
// Resamples the six cube faces into the equirectangular panorama.
// Color: mean of 2x2 bilinear samples inside the pixel (anti-aliasing).
// Distance: exact intersection of the pixel's ray with the plane of a
// triangle seen by the cube texels around it. Where the four texels around
// the ray see one continuous surface, the candidate plane whose hit lies
// nearest the bilinear distance wins: at a concave corner the chord lies
// below the true distance (the nearer plane is right), at a convex edge
// above it (the farther plane is right). Across a silhouette the nearest
// texel's plane is used, or that texel's own distance where its plane
// would mislead (grazing angles).
#include "projection.glsl"
in vec2 texCoord;
uniform samplerCube colorCube;            // linear filtering, seamless
uniform samplerCube planeCube;            // nearest: unit normal facing the camera, n . p
uniform samplerCube distanceCube;         // nearest
uniform samplerCube distanceCubeLinear;   // the same texture, linear filtering
uniform vec2 panoramaSize;
layout(location = 0) out vec4 outColor;
layout(location = 1) out float outDistance;

// Distance along direction to a plane (n, w), or -1 when it is not hit in front.
float planeHit(vec4 plane, vec3 direction) {
  if (dot(plane.xyz, plane.xyz) < 0.5) return -1.0;
  float cosine = dot(plane.xyz, direction);
  return cosine < -1e-4 ? plane.w / cosine : -1.0;
}

void main() {
  vec2 pixel = floor(texCoord * panoramaSize);
  vec3 color = vec3(0.0);
  for (int i = 0; i < 4; ++i) {
    vec2 offset = vec2(0.25 + 0.5 * float(i & 1), 0.25 + 0.5 * float(i >> 1));
    color += texture(colorCube, equirectDirection(pixel + offset, panoramaSize, 0.0)).rgb;
  }
  outColor = vec4(color * 0.25, 1.0);

  vec3 direction = equirectDirection(pixel + 0.5, panoramaSize, 0.0);
  vec4 distances = textureGather(distanceCube, direction, 0);
  float nearDistance = min(min(distances.x, distances.y), min(distances.z, distances.w));
  float farDistance = max(max(distances.x, distances.y), max(distances.z, distances.w));
  bool continuous = !isinf(farDistance) && farDistance <= 1.1 * nearDistance;

  float texelDistance = texture(distanceCube, direction).r;
  float distance = texelDistance;
  float nearestHit = planeHit(texture(planeCube, direction), direction);
  if (nearestHit > 0.0 && abs(nearestHit - texelDistance) <= 0.02 * texelDistance) distance = nearestHit;

  if (continuous) {
    float chord = texture(distanceCubeLinear, direction).r;
    vec4 nx = textureGather(planeCube, direction, 0);
    vec4 ny = textureGather(planeCube, direction, 1);
    vec4 nz = textureGather(planeCube, direction, 2);
    vec4 nw = textureGather(planeCube, direction, 3);
    float best = abs(distance - chord);
    for (int i = 0; i < 4; ++i) {
      float t = planeHit(vec4(nx[i], ny[i], nz[i], nw[i]), direction);
      if (t > 0.0 && abs(t - chord) < best && abs(t - chord) <= 0.02 * chord) {
        best = abs(t - chord);
        distance = t;
      }
    }
  }
  outDistance = distance;
}
