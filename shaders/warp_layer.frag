#version 450 core
// A reference's layer: its nearest surface per pixel (the depth test),
// linear color and 1 / distance (interpolated perspective-correctly, as
// the CPU reference does). Alpha -1 (the clear value) means uncovered.
in vec3 vertexColor;
in float inverseDistance;
layout(location = 0) out vec4 layer;
void main() { layer = vec4(vertexColor, inverseDistance); }
