#version 450 core
// Shades the scene (texture x vertex color x base color, lit by a lightmap
// or by ambient + point lights, Blinn-Phong highlights that move with the
// viewpoint) and records, per fragment, the plane of its triangle so that
// the panorama's distance can be computed exactly along any ray.
#include "scene_surface.glsl"
in vec3 worldNormal;
in vec2 surfaceLightmapUv;

layout(location = 0) out vec4 outColor;     // linear RGB
layout(location = 1) out vec4 outPlane;     // unit normal facing the camera, n . p
layout(location = 2) out float outDistance; // metres

const int kMaxLights = 16;
uniform bool hasLightmap;
uniform sampler2D lightmapTexture;
uniform float lightmapScale;
uniform float specularStrength;
uniform float shininess;
uniform vec3 ambient;
uniform int lightCount;
uniform vec3 lightPositions[kMaxLights];  // relative to the camera
uniform vec3 lightColors[kMaxLights];
uniform float lightRanges[kMaxLights];

void main() {
  vec4 albedo = surfaceAlbedo();
  vec4 plane = surfacePlane();

  // Walls are seen from both sides: light the side facing the camera.
  vec3 n = normalize(worldNormal);
  if (dot(n, relativePosition) > 0.0) n = -n;
  vec3 toEye = normalize(-relativePosition);

  vec3 light;
  vec3 highlight = vec3(0.0);
  if (hasLightmap) {
    light = texture(lightmapTexture, surfaceLightmapUv).rgb * lightmapScale;
  } else {
    light = ambient;
    for (int i = 0; i < lightCount; ++i) {
      vec3 toLight = lightPositions[i] - relativePosition;
      float d = length(toLight);
      vec3 l = toLight / d;
      float falloff = 1.0 / (1.0 + (d / lightRanges[i]) * (d / lightRanges[i]));
      light += lightColors[i] * max(dot(n, l), 0.0) * falloff;
      if (specularStrength > 0.0) {
        vec3 h = normalize(l + toEye);
        highlight += lightColors[i] * falloff * specularStrength * pow(max(dot(n, h), 0.0), shininess);
      }
    }
  }
  outColor = vec4(albedo.rgb * light + highlight, 1.0);
  outPlane = plane;
  outDistance = length(relativePosition);
}
