#version 450 core
// The scene for a capture of distances only (the walkable region's
// probes): the same surfaces, planes and distances as shaders/scene.frag,
// without its shading. Linked with shaders/scene.vert, whose normal and
// lightmap coordinates this leaves unread, so the vertices that reach the
// rasterizer carry fewer attributes.
#include "scene_surface.glsl"

layout(location = 1) out vec4 outPlane;     // unit normal facing the camera, n . p
layout(location = 2) out float outDistance; // metres

void main() {
  surfaceAlbedo();
  outPlane = surfacePlane();
  outDistance = length(relativePosition);
}
