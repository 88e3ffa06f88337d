#version 450 core
// The frame as shown: display (sRGB-encoded) colour of the blended and
// possibly filled linear image; pixels still unknown get holeColor.
uniform sampler2D image;
uniform vec3 holeColor;  // display colour
out vec4 outColor;

float linearToSrgb(float linear) {
  float c = clamp(linear, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

void main() {
  vec4 value = texelFetch(image, ivec2(gl_FragCoord.xy), 0);
  outColor = value.a < 0.0 ? vec4(holeColor, 1.0) : vec4(linearToSrgb(value.r), linearToSrgb(value.g), linearToSrgb(value.b), 1.0);
}
