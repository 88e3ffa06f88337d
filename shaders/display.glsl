// Display (sRGB-encoded) colour of a linear one, as core/image/color.h.
float linearToSrgb(float linear) {
  float c = clamp(linear, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

vec4 displayColor(vec3 linear) { return vec4(linearToSrgb(linear.r), linearToSrgb(linear.g), linearToSrgb(linear.b), 1.0); }
