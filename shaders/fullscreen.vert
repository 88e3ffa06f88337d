#version 450 core
// One triangle covering the viewport at depth 0 (infinity in the capture's
// reversed-depth projection); texCoord spans [0, 1] over the viewport.
out vec2 texCoord;
void main() {
  vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  texCoord = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
