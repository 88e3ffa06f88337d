// Display (sRGB-encoded) colour of a linear one, as core/image/color.h.
float linearToSrgb(float linear) {
  float c = clamp(linear, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

vec4 displayColor(vec3 linear) { return vec4(linearToSrgb(linear.r), linearToSrgb(linear.g), linearToSrgb(linear.b), 1.0); }

// Google's Turbo colour map in display colours, as core/image/color.cpp's
// falseColor (the same polynomial): 0 dark blue, 0.5 green, 1 dark red.
vec3 falseColor(float t) {
  float x = clamp(t, 0.0, 1.0);
  vec4 v4 = vec4(1.0, x, x * x, x * x * x);
  vec2 v2 = vec2(v4.z * v4.z, v4.w * v4.z);
  vec3 color = vec3(dot(v4, vec4(0.13572138, 4.61539260, -42.66032258, 132.13108234)) + dot(v2, vec2(-152.94239396, 59.28637943)),
                    dot(v4, vec4(0.09140261, 2.19418839, 4.84296658, -14.18503333)) + dot(v2, vec2(4.27729857, 2.82956604)),
                    dot(v4, vec4(0.10667330, 12.64194608, -60.58204836, 110.36276771)) + dot(v2, vec2(-89.90310912, 27.34824973)));
  return clamp(color, 0.0, 1.0);
}
