#version 450 core
// One reference panorama as a grid mesh displaced by its distance texture
// (the CPU reference warp's mesh, core/synthesis/warp.h): vertex i is pixel
// (i mod W, i div W), W*H and W*H+1 are the poles; a vertex at infinity
// (sky) is a direction, w = 0. A simplified mesh gives its vertices
// explicitly (vertexPoint, the same w convention) and its colour comes from
// the fragment shader's lookup along the source ray.
#include "projection.glsl"
uniform sampler2D colorTexture;
uniform sampler2D distanceTexture;
uniform ivec2 panoramaSize;
uniform float panoramaYaw;
uniform vec3 sourcePosition;
uniform vec2 poleDistances;
uniform vec3 poleColors[2];
uniform mat4 viewProjection;  // world -> clip, reversed depth, no far plane
uniform vec3 cameraPosition;
uniform bool explicitVertices;
layout(location = 0) in vec4 vertexPoint;

out vec3 vertexColor;
out float finite;           // 1 for a surface point, 0 for a direction at infinity (sky)
out vec3 worldPoint;        // the surface point, for the layer's reliability (a direction at infinity)
out float vertexFringe;     // the pixel's silhouette fringe flag (core/synthesis/silhouette_fringe.h): 1 - the colour's alpha

void main() {
  vertexFringe = 0.0;
  if (explicitVertices) {
    vertexColor = vec3(0.0);
    worldPoint = vertexPoint.xyz;
    gl_Position = viewProjection * vertexPoint;
    finite = vertexPoint.w == 0.0 ? 0.0 : 1.0;
    return;
  }
  int pixels = panoramaSize.x * panoramaSize.y;
  vec3 direction;
  float distance;
  if (gl_VertexID >= pixels) {
    int pole = gl_VertexID - pixels;
    direction = vec3(0.0, 0.0, pole == 0 ? 1.0 : -1.0);
    distance = poleDistances[pole];
    vertexColor = poleColors[pole];
  } else {
    ivec2 pixel = ivec2(gl_VertexID % panoramaSize.x, gl_VertexID / panoramaSize.x);
    direction = equirectDirection(vec2(pixel) + 0.5, vec2(panoramaSize), panoramaYaw);
    distance = texelFetch(distanceTexture, pixel, 0).r;
    vec4 texel = texelFetch(colorTexture, pixel, 0);
    vertexColor = texel.rgb;
    vertexFringe = 1.0 - texel.a;
  }
  if (isinf(distance)) {
    gl_Position = viewProjection * vec4(direction, 0.0);
    finite = 0.0;
    worldPoint = direction;
  } else {
    vec3 world = sourcePosition + distance * direction;
    gl_Position = viewProjection * vec4(world, 1.0);
    finite = 1.0;
    worldPoint = world;
  }
}
