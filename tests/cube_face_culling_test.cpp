// Which cube faces a triangle can show on: exact answers for triangles
// whose faces are known, no face ever left out that a triangle meets, and
// the capture drawing each triangle only where it can show.

#include "render/capture/cube_face_culling.h"
#include "render/capture/panorama_capturer.h"
#include "render/gl/gl_context.h"
#include "scene/scene_description.h"

#include <doctest/doctest.h>

#include <random>

namespace triwalk {

namespace {

uint8_t facesOf(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  return cubeFacesTouched(cubeFaceOutcode(a), cubeFaceOutcode(b), cubeFaceOutcode(c));
}

// The closed cone face f sees, by its definition (GL's face order).
bool inFaceCone(glm::vec3 p, int face) {
  const int axis = face / 2;
  const float d = face % 2 == 0 ? p[axis] : -p[axis];
  return std::abs(p[(axis + 1) % 3]) <= d && std::abs(p[(axis + 2) % 3]) <= d;
}

constexpr uint8_t kPlusX = 1, kMinusX = 2, kPlusY = 4, kMinusY = 8, kPlusZ = 16, kMinusZ = 32;

}  // namespace

TEST_CASE("cube face culling: a triangle shows on exactly the faces whose cones it meets") {
  // Small, straight ahead of each face.
  CHECK(facesOf({3.0f, 0.1f, 0.1f}, {3.0f, 0.3f, 0.1f}, {3.0f, 0.1f, 0.3f}) == kPlusX);
  CHECK(facesOf({-3.0f, 0.1f, 0.1f}, {-3.0f, 0.3f, 0.1f}, {-3.0f, 0.1f, 0.3f}) == kMinusX);
  CHECK(facesOf({0.1f, 3.0f, 0.1f}, {0.3f, 3.0f, 0.1f}, {0.1f, 3.0f, 0.3f}) == kPlusY);
  CHECK(facesOf({0.1f, -3.0f, 0.1f}, {0.3f, -3.0f, 0.1f}, {0.1f, -3.0f, 0.3f}) == kMinusY);
  CHECK(facesOf({0.1f, 0.1f, 3.0f}, {0.3f, 0.1f, 3.0f}, {0.1f, 0.3f, 3.0f}) == kPlusZ);
  CHECK(facesOf({0.1f, 0.1f, -3.0f}, {0.3f, 0.1f, -3.0f}, {0.1f, 0.3f, -3.0f}) == kMinusZ);
  // Across the edge between +X and +Y (the direction (1, 1, 0)).
  CHECK(facesOf({2.0f, 1.5f, 0.1f}, {1.5f, 2.0f, 0.1f}, {1.8f, 1.8f, 0.3f}) == (kPlusX | kPlusY));
  // On the diagonal (1, 1, 1), where three faces meet: the corner of each.
  CHECK(facesOf({2.0f, 2.0f, 2.0f}, {2.1f, 2.0f, 2.0f}, {2.0f, 2.1f, 2.0f}) == (kPlusX | kPlusY | kPlusZ));
  // A floor under the eye reaching out on every side: every face but the ceiling's.
  CHECK(facesOf({-30.0f, -30.0f, -1.6f}, {30.0f, -30.0f, -1.6f}, {0.0f, 60.0f, -1.6f}) == uint8_t(63 & ~kPlusZ));
  // A wall beside the eye, ahead on +X and behind it: +X, -X and the sides it reaches.
  CHECK(facesOf({-5.0f, 1.0f, -1.0f}, {5.0f, 1.0f, -1.0f}, {0.0f, 1.0f, 1.0f}) ==
        (kPlusX | kMinusX | kPlusY | kPlusZ | kMinusZ));
  // A point on a face's side plane (x = y) is in both cones (closed), not beyond.
  CHECK(facesOf({2.0f, 2.0f, 0.0f}, {2.0f, 2.0f, 0.0f}, {2.0f, 2.0f, 0.0f}) == (kPlusX | kPlusY));
}

TEST_CASE("cube face culling never leaves out a triangle that meets a face, and leaves out most faces of small ones") {
  std::mt19937 random(20261127);
  std::uniform_real_distribution<float> coordinate(-4.0f, 4.0f), offset(-0.6f, 0.6f), weight(0.0f, 1.0f);
  int triangles = 0, facesKept = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const glm::vec3 centre(coordinate(random), coordinate(random), coordinate(random));
    const glm::vec3 scale = trial % 4 == 0 ? glm::vec3(8.0f) : glm::vec3(1.0f);  // a quarter are large
    glm::vec3 corners[3];
    for (glm::vec3& corner : corners)
      corner = centre + scale * glm::vec3(offset(random), offset(random), offset(random));
    const uint8_t faces = facesOf(corners[0], corners[1], corners[2]);
    for (int face = 0; face < kCubeFaces; ++face) {
      if (faces & (1u << face)) continue;
      // Left out: no point of the triangle (corners, edges and inside) lies in the face's cone.
      bool met = false;
      for (int i = 0; i <= 24 && !met; ++i) {
        for (int j = 0; i + j <= 24 && !met; ++j) {
          const float u = float(i) / 24.0f, v = float(j) / 24.0f;
          met = inFaceCone(corners[0] + u * (corners[1] - corners[0]) + v * (corners[2] - corners[0]), face);
        }
      }
      for (int k = 0; k < 16 && !met; ++k) {
        float u = weight(random), v = weight(random);
        if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
        met = inFaceCone(corners[0] + u * (corners[1] - corners[0]) + v * (corners[2] - corners[0]), face);
      }
      INFO("trial ", trial, ", face ", face);
      CHECK_FALSE(met);
    }
    if (trial % 4 != 0) ++triangles, facesKept += __builtin_popcount(faces);
  }
  // A small triangle away from the eye meets one face, two or three near an edge or corner.
  CHECK(double(facesKept) / triangles < 1.6);
}

TEST_CASE("the outcodes of many vertices at once are each vertex's own, to the bit") {
  // Points on the planes (components equal up to sign, zeros of either
  // sign) and random ones, around eyes that make the subtraction round;
  // 4k + 3 of them, so the lanes and the scalar tail both run.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-20.0f, 20.0f);
  std::vector<glm::vec3> points;
  for (const float a : {0.0f, -0.0f, 1.0f, -1.0f, 2.5f}) {
    for (const float b : {0.0f, -0.0f, 1.0f, -1.0f, -2.5f}) points.push_back({a, b, -a});
  }
  while (points.size() % 4 != 3 || points.size() < 4003) {
    const float x = coordinate(random);
    points.push_back({x, points.size() % 3 == 0 ? -x : coordinate(random), coordinate(random)});
  }
  for (const glm::vec3 eye : {glm::vec3(0.0f), glm::vec3(0.1f, -7.3f, 1.6f), glm::vec3(1.0f, 1.0f, -1.0f)}) {
    std::vector<uint32_t> codes(points.size());
    cubeFaceOutcodes(points, eye, codes);
    size_t differing = 0;
    for (size_t i = 0; i < points.size(); ++i) differing += codes[i] != cubeFaceOutcode(points[i] - eye);
    INFO("eye " << eye.x << ", " << eye.y << ", " << eye.z);
    CHECK(differing == 0);
  }
}

TEST_CASE("a capture draws each triangle only on the cube faces it can show on") {
  auto context = createHeadlessContext();
  const Scene scene = loadSceneDescription(builtinScenePath());
  PanoramaCapturer capturer(scene, 256);
  const Panorama panorama = capturer.capture({5.0f, 2.5f, 1.6f});
  CHECK(panorama.distance.pixelCount() == 256u * 128u);
  // Six faces of the whole scene would be 6 x its triangles; the floor,
  // the ceiling and the walls that run past the eye show on several faces.
  INFO(capturer.trianglesDrawn(), " of ", scene.triangleCount());
  CHECK(capturer.trianglesDrawn() >= scene.triangleCount());
  CHECK(capturer.trianglesDrawn() < 2 * scene.triangleCount());
}

}  // namespace triwalk
