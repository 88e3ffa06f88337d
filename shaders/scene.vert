#version 450 core
// Scene geometry for capture, positioned relative to the camera so that
// the fragment shader gets camera-relative positions in metres.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 3) in vec2 lightmapUv;
layout(location = 4) in vec4 color;

uniform mat4 viewProjection;  // camera at the origin
uniform vec3 eye;             // camera position, world

out vec3 relativePosition;
out vec3 worldNormal;
out vec2 surfaceUv;
out vec2 surfaceLightmapUv;
out vec4 vertexColor;

void main() {
  relativePosition = position - eye;
  worldNormal = normal;
  surfaceUv = uv;
  surfaceLightmapUv = lightmapUv;
  vertexColor = color;
  gl_Position = viewProjection * vec4(relativePosition, 1.0);
}
