// What every scene fragment of a capture computes, whatever it writes:
// whether a surface is there (the alpha test; no garbage from zero-area
// triangles) and that surface's plane. shaders/scene.frag shades it too;
// shaders/scene_distance.frag, for the region's probes, does not.
in vec3 relativePosition;
in vec2 surfaceUv;
in vec4 vertexColor;

uniform vec3 baseColor;
uniform bool hasDiffuse;
uniform sampler2D diffuseTexture;
uniform bool useVertexColor;
uniform bool alphaTest;

// The surface's albedo (texture x vertex color x base color); discards
// the fragment where the alpha test removes the surface or there is none.
vec4 surfaceAlbedo() {
  vec4 albedo = vec4(baseColor, 1.0);
  if (hasDiffuse) albedo *= texture(diffuseTexture, surfaceUv);
  if (useVertexColor) albedo *= vertexColor;
  if (alphaTest && albedo.a < 0.5) discard;
  // llvmpipe interpolates garbage (NaN, inf) across zero-area triangles,
  // which imported meshes have: such a fragment is no surface at all.
  if (any(isnan(relativePosition)) || any(isinf(relativePosition))) discard;
  return albedo;
}

// The exact plane of this triangle (flat, from screen derivatives): its
// unit normal facing the camera, and n . p.
vec4 surfacePlane() {
  vec3 faceNormal = normalize(cross(dFdx(relativePosition), dFdy(relativePosition)));
  if (dot(faceNormal, relativePosition) > 0.0) faceNormal = -faceNormal;
  return vec4(faceNormal, dot(faceNormal, relativePosition));
}
