// The sky at infinity: a gradient from horizon to zenith, a ground tone
// below the horizon and a sun disc. Depends on direction only, so every
// panorama sees the same sky and it warps as a direction.
uniform vec3 skyZenith;
uniform vec3 skyHorizon;
uniform vec3 skyGround;
uniform vec3 skySunDirection;
uniform vec3 skySunColor;

vec3 skyColor(vec3 direction) {
  vec3 d = normalize(direction);
  vec3 color;
  if (d.z >= 0.0) {
    color = mix(skyHorizon, skyZenith, pow(d.z, 0.6));
  } else {
    color = mix(skyHorizon, skyGround, clamp(-d.z * 6.0, 0.0, 1.0));
  }
  float sun = max(dot(d, normalize(skySunDirection)), 0.0);
  color += skySunColor * (pow(sun, 2000.0) + 0.02 * pow(sun, 40.0));
  return color;
}
