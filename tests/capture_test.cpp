// Headless capture: exact distances and colors inside a box of known size,
// EGL and OSMesa agree, and the built-in scene captures as designed.

#include "core/geometry/projection.h"
#include "core/image/image_compare.h"
#include "core/io/dataset.h"
#include "core/io/png_io.h"
#include "core/synthesis/simplified_mesh_store.h"
#include "render/capture/dataset_capture.h"
#include "render/capture/panorama_capturer.h"
#include "render/capture/truth_frame_renderer.h"
#include "render/gl/gl_context.h"
#include "scene/mesh_builder.h"
#include "scene/scene_description.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <fstream>

namespace triwalk {

namespace {

constexpr glm::vec3 kBoxLower{0.0f, 0.0f, 0.0f};
constexpr glm::vec3 kBoxUpper{4.0f, 3.0f, 2.5f};
constexpr glm::vec3 kCamera{1.3f, 1.1f, 1.2f};

// Wall order: -x, +x, -y, +y, floor, ceiling; linear colors.
const glm::vec3 kWallColors[6] = {{0.8f, 0.1f, 0.1f}, {0.1f, 0.8f, 0.1f}, {0.1f, 0.1f, 0.8f},
                                  {0.8f, 0.8f, 0.1f}, {0.1f, 0.8f, 0.8f}, {0.8f, 0.1f, 0.8f}};

// A closed room lit only by a white ambient term, so every wall shows its
// base color exactly.
Scene boxRoom() {
  Scene scene;
  scene.name = "box";
  scene.ambient = glm::vec3(1.0f);
  const glm::vec3 size = kBoxUpper - kBoxLower;
  const glm::vec3 x(size.x, 0, 0), y(0, size.y, 0), z(0, 0, size.z);
  for (int wall = 0; wall < 6; ++wall) {
    SceneMaterial material;
    material.baseColor = kWallColors[wall];
    scene.materials.push_back(material);
    MeshBuilder builder(wall, 1.0f);
    switch (wall) {  // normals face into the room
      case 0: builder.addQuad(kBoxLower, y, z, 0.5f); break;
      case 1: builder.addQuad(kBoxLower + x, z, y, 0.5f); break;
      case 2: builder.addQuad(kBoxLower, z, x, 0.5f); break;
      case 3: builder.addQuad(kBoxLower + y, x, z, 0.5f); break;
      case 4: builder.addQuad(kBoxLower, x, y, 0.5f); break;
      case 5: builder.addQuad(kBoxLower + z, y, x, 0.5f); break;
    }
    scene.meshes.push_back(builder.take());
  }
  scene.walkableArea.min = {0.5f, 0.5f};
  scene.walkableArea.max = {3.5f, 2.5f};
  scene.walkableArea.eyeHeight = 1.2f;
  return scene;
}

// Distance from the camera to the box along a direction, and the wall hit.
float rayToBox(glm::vec3 direction, int& wall) {
  float nearest = INFINITY;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(direction[axis]) < 1e-9f) continue;
    const float plane = direction[axis] > 0.0f ? kBoxUpper[axis] : kBoxLower[axis];
    const float t = (plane - kCamera[axis]) / direction[axis];
    if (t > 0.0f && t < nearest) {
      nearest = t;
      wall = 2 * axis + (direction[axis] > 0.0f ? 1 : 0);
    }
  }
  return nearest;
}

Panorama captureBox(HeadlessBackend backend, int width) {
  auto context = createHeadlessContext(backend);
  const Scene scene = boxRoom();
  PanoramaCapturer capturer(scene, width);
  return capturer.capture(kCamera);
}

void checkBoxPanorama(const Panorama& panorama) {
  const EquirectProjection projection{panorama.width(), panorama.height(), 0.0f};
  float worstRelativeError = 0.0f;
  size_t colorChecked = 0, colorWrong = 0;
  for (int v = 0; v < panorama.height(); ++v) {
    for (int u = 0; u < panorama.width(); ++u) {
      int wall = -1;
      const float expected = rayToBox(projection.pixelDirection(u, v), wall);
      const float captured = panorama.distance.at(u, v);
      worstRelativeError = std::max(worstRelativeError, std::abs(captured - expected) / expected);

      // Color: away from wall edges (bilinear filtering of the cube faces
      // blends texels there), i.e. where the rays one pixel around hit the
      // same wall; a cube texel is smaller than a panorama pixel.
      bool uniform = true;
      for (int dv = -1; dv <= 1; ++dv) {
        for (int du = -1; du <= 1; ++du) {
          int neighbourWall = -1;
          rayToBox(projection.direction({float(u + du) + 0.5f, float(v + dv) + 0.5f}), neighbourWall);
          uniform &= neighbourWall == wall;
        }
      }
      if (!uniform) continue;
      ++colorChecked;
      const glm::vec3 difference = glm::abs(panorama.color.at(u, v) - kWallColors[wall]);
      colorWrong += std::max({difference.r, difference.g, difference.b}) > 2e-3f;
    }
  }
  INFO("worst relative distance error " << worstRelativeError);
  CHECK(worstRelativeError <= 0.005f);
  CHECK(colorChecked > panorama.color.pixelCount() * 9 / 10);
  CHECK(colorWrong == 0);
}

// The image's mean colour everywhere.
Rgb8Image constantImageLike(const Rgb8Image& image) {
  glm::dvec3 sum(0.0);
  for (const glm::u8vec3& pixel : image.pixels) sum += glm::dvec3(pixel);
  Rgb8Image constant(image.width, image.height);
  for (glm::u8vec3& pixel : constant.pixels) pixel = glm::u8vec3(sum / double(image.pixelCount()) + 0.5);
  return constant;
}

}  // namespace

TEST_CASE("capture inside a box: distance within 0.5% everywhere, wall colors exact (EGL)") {
  checkBoxPanorama(captureBox(HeadlessBackend::Egl, 512));
}

TEST_CASE("capture inside a box: distance within 0.5% everywhere, wall colors exact (OSMesa)") {
  checkBoxPanorama(captureBox(HeadlessBackend::OsMesa, 256));
}

TEST_CASE("EGL and OSMesa capture the same panorama") {
  const Panorama egl = captureBox(HeadlessBackend::Egl, 256);
  const Panorama osmesa = captureBox(HeadlessBackend::OsMesa, 256);
  float largest = 0.0f;
  for (size_t i = 0; i < egl.color.pixelCount(); ++i) {
    const glm::vec3 d = glm::abs(egl.color.pixels[i] - osmesa.color.pixels[i]);
    largest = std::max({largest, d.r, d.g, d.b, std::abs(egl.distance.pixels[i] - osmesa.distance.pixels[i])});
  }
  CHECK(largest <= 1e-5f);
}

// The box room with three screens inside, each textured and alpha-tested:
// a grate (a texture whose every other column is transparent) at x = 3,
// an opaque texture with vertex alpha 0.3 (every fragment discarded) at
// x = 0.6, and an opaque texture at y = 2.5.
Scene boxRoomWithScreens() {
  Scene scene = boxRoom();
  SceneTexture grate{"grate", 8, 8, std::vector<uint8_t>(8 * 8 * 4, 255)};
  for (size_t texel = 0; texel < 64; ++texel) grate.rgba[4 * texel + 3] = texel % 2 == 0 ? 0 : 255;
  scene.textures.push_back(grate);
  scene.textures.push_back({"opaque", 8, 8, std::vector<uint8_t>(8 * 8 * 4, 255)});
  const auto addScreen = [&](int texture, bool vertexAlpha, glm::vec3 origin, glm::vec3 u, glm::vec3 v) {
    SceneMaterial material;
    material.diffuseTexture = texture;
    material.alphaTest = true;
    material.useVertexColor = vertexAlpha;
    scene.materials.push_back(material);
    MeshBuilder builder(int(scene.materials.size()) - 1, 0.4f);
    builder.addQuad(origin, u, v, 0.5f);
    SceneMesh mesh = builder.take();
    if (vertexAlpha) {
      for (SceneVertex& vertex : mesh.vertices) vertex.color.a = 0.3f;
    }
    scene.meshes.push_back(std::move(mesh));
  };
  addScreen(0, false, {3.0f, 0.3f, 0.3f}, {0.0f, 2.4f, 0.0f}, {0.0f, 0.0f, 1.9f});
  addScreen(1, true, {0.6f, 0.3f, 0.3f}, {0.0f, 2.4f, 0.0f}, {0.0f, 0.0f, 1.9f});
  addScreen(1, false, {0.3f, 2.5f, 0.3f}, {3.4f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.9f});
  return scene;
}

TEST_CASE("the distance-only capture has the full capture's distances to the bit, through a grate and vertex alpha") {
  auto context = createHeadlessContext();
  const Scene scene = boxRoomWithScreens();
  PanoramaCapturer capturer(scene, 256);
  const Panorama full = capturer.capture(kCamera);
  const ScalarImage distance = capturer.captureDistance(kCamera);
  REQUIRE(distance.pixelCount() == full.distance.pixelCount());
  CHECK(std::memcmp(distance.pixels.data(), full.distance.pixels.data(), distance.pixels.size() * sizeof(float)) == 0);

  // What the screens leave visible: the wall through half the grate, the
  // wall behind the vertex-alpha screen everywhere, the opaque screen itself.
  const EquirectProjection projection{distance.width, distance.height, 0.0f};
  int grate = 0, throughGrate = 0, hidden = 0, behindHidden = 0, opaque = 0, other = 0;
  for (int v = 0; v < distance.height; ++v) {
    for (int u = 0; u < distance.width; ++u) {
      const glm::vec3 direction = projection.pixelDirection(u, v);
      const glm::vec3 onGrate = kCamera + direction * ((3.0f - kCamera.x) / direction.x);
      const float d = distance.at(u, v);
      if (direction.x > 0.0f && onGrate.y > 0.35f && onGrate.y < 2.65f && onGrate.z > 0.35f && onGrate.z < 2.15f) {
        const float toGrate = (3.0f - kCamera.x) / direction.x;
        if (std::abs(d - toGrate) < 0.01f * toGrate)
          ++grate;
        else if (std::abs(d - (4.0f - kCamera.x) / direction.x) < 0.01f * d)
          ++throughGrate;
        else
          ++other;
      }
      const glm::vec3 onHidden = kCamera + direction * ((0.6f - kCamera.x) / direction.x);
      if (direction.x < 0.0f && onHidden.y > 0.35f && onHidden.y < 2.4f && onHidden.z > 0.35f && onHidden.z < 2.15f) {
        if (std::abs(d - (0.6f - kCamera.x) / direction.x) < 0.01f * d)
          ++hidden;
        else if (std::abs(d - (0.0f - kCamera.x) / direction.x) < 0.01f * d)
          ++behindHidden;
      }
      if (direction.y > 0.3f && std::abs(direction.x) < 0.2f && std::abs(direction.z) < 0.2f) {
        opaque += std::abs(d - (2.5f - kCamera.y) / direction.y) < 0.01f * d;
      }
    }
  }
  INFO("grate ", grate, ", through it ", throughGrate, ", neither ", other, "; hidden screen ", hidden, ", behind it ",
       behindHidden, "; opaque ", opaque);
  CHECK(grate > 300);
  CHECK(throughGrate > 300);
  CHECK(hidden == 0);
  CHECK(behindHidden > 1000);
  CHECK(opaque > 100);
}

TEST_CASE("built-in scene: tens of thousands of triangles over a 10 x 5 m walkable area") {
  const Scene scene = loadSceneDescription(builtinScenePath());
  CHECK(scene.triangleCount() >= 20000);
  CHECK(scene.triangleCount() <= 100000);
  const glm::vec2 size = scene.walkableArea.max - scene.walkableArea.min;
  CHECK(size.x == doctest::Approx(10.0));
  CHECK(size.y == doctest::Approx(5.0));
  CHECK(scene.materials.size() >= 8);
  bool glossy = false;
  for (const SceneMaterial& material : scene.materials) glossy |= material.specular > 0.0f;
  CHECK(glossy);
}

TEST_CASE("built-in scene: sky through the skylight, floor at eye height, neighbouring rooms through openings") {
  auto context = createHeadlessContext();
  const Scene scene = loadSceneDescription(builtinScenePath());
  PanoramaCapturer capturer(scene, 256);
  const glm::vec3 underSkylight(5.0f, 2.6f, 1.6f);
  const Panorama panorama = capturer.capture(underSkylight);
  const EquirectProjection projection{256, 128, 0.0f};
  // Straight up: sky at infinity; straight down: the floor 1.6 m below.
  CHECK(std::isinf(panorama.distance.at(10, 0)));
  const float down = panorama.distance.at(10, 127);
  const float expectedDown = 1.6f / -projection.pixelDirection(10, 127).z;
  CHECK(std::abs(down - expectedDown) <= 0.005f * expectedDown);
  // At eye height: west through the window (past the stone pillar in front
  // of it) is open sky; east through the
  // doorway, south through the window and north through the courtyard
  // opening are surfaces of the neighbouring rooms.
  const int west = 253, south = 64, east = 128, north = 192, horizon = 64;
  CHECK(std::isinf(panorama.distance.at(west, horizon)));
  CHECK(panorama.distance.at(south, horizon) > 5.0f);
  CHECK(panorama.distance.at(south, horizon) < 9.0f);
  CHECK(panorama.distance.at(east, horizon) > 7.0f);
  CHECK(panorama.distance.at(east, horizon) < 11.0f);
  CHECK(panorama.distance.at(north, horizon) > 4.0f);
  CHECK(panorama.distance.at(north, horizon) < 11.5f);

}

TEST_CASE("a truth frame through a pinhole at a cube face's pose equals that face of the capture") {
  auto context = createHeadlessContext();
  const Scene scene = loadSceneDescription(builtinScenePath());
  PanoramaCapturer capturer(scene, 256);
  const int face = defaultCubeFaceSize(256);
  const glm::vec3 eye(5.0f, 2.6f, 1.6f);
  capturer.capture(eye);
  // GL's +Y face looks along +y with +z up: a pinhole at yaw 90, pitch 0,
  // 90 degrees wide and high, one sample a pixel.
  PinholeCamera camera;
  camera.width = camera.height = face;
  camera.verticalFovDegrees = 90.0f;
  camera.position = eye;
  camera.yawDegrees = 90.0f;
  TruthFrameRenderer truth(scene, face, face, 1);
  const Rgb8Image fromTruth = toDisplayImage(truth.render(camera));
  const Rgb8Image fromCube = toDisplayImage(capturer.cubeFaceColor(2));
  CHECK(differingPixelFraction(fromTruth, fromCube, 1) < 0.002);
  CHECK(psnr(fromTruth, fromCube) > 50.0);
  // Not a uniform view: walls, furniture and sky of the built-in scene.
  CHECK(psnr(fromTruth, constantImageLike(fromTruth)) < 30.0);
  // Looking the other way is another picture.
  camera.yawDegrees = 270.0f;
  CHECK(psnr(toDisplayImage(truth.render(camera)), fromCube) < 25.0);
}

TEST_CASE("a glossy surface changes color with the viewpoint, a matte one does not") {
  auto context = createHeadlessContext();
  // One floor quad lit by one light; the specular highlight of a point is
  // strongest from the mirror direction of the light.
  for (const float specular : {0.0f, 1.0f}) {
    Scene scene;
    scene.ambient = glm::vec3(0.1f);
    scene.lights.push_back({{0.0f, 0.0f, 2.0f}, glm::vec3(1.0f), 10.0f});
    SceneMaterial material;
    material.baseColor = glm::vec3(0.4f);
    material.specular = specular;
    material.shininess = 40.0f;
    scene.materials.push_back(material);
    MeshBuilder builder(0, 1.0f);
    builder.addQuad({-5.0f, -5.0f, 0.0f}, {10.0f, 0.0f, 0.0f}, {0.0f, 10.0f, 0.0f}, 1.0f);
    scene.meshes.push_back(builder.take());
    PanoramaCapturer capturer(scene, 256);
    const EquirectProjection projection{256, 128, 0.0f};
    const glm::vec3 floorPoint(1.0f, 0.0f, 0.0f);
    const glm::vec3 mirror(2.0f, 0.0f, 2.0f), aside(1.0f, 2.0f, 1.5f);
    const glm::vec2 pixelMirror = projection.imagePoint(floorPoint - mirror);
    const glm::vec2 pixelAside = projection.imagePoint(floorPoint - aside);
    const glm::vec3 fromMirror = capturer.capture(mirror).color.at(int(pixelMirror.x), int(pixelMirror.y));
    const glm::vec3 fromAside = capturer.capture(aside).color.at(int(pixelAside.x), int(pixelAside.y));
    INFO("specular " << specular);
    if (specular > 0.0f) {
      CHECK(fromMirror.r > fromAside.r + 0.2f);
    } else {
      CHECK(fromMirror.r == doctest::Approx(fromAside.r).epsilon(0.01));
    }
  }
}

TEST_CASE("capture writes a complete data set that opens, and refuses to overwrite other directories") {
  testing::TemporaryDirectory directory;
  auto context = createHeadlessContext();
  const Scene scene = boxRoom();
  CaptureOptions options;
  options.paths = 3;
  options.perPath = 2;
  options.width = 64;
  options.probes = 2;
  options.quiet = true;
  const CaptureSummary summary = captureDataset(scene, "box", options, directory / "box");
  CHECK(summary.samples == 6);
  CHECK(summary.probes == 2);
  const Dataset dataset = Dataset::open(directory / "box");
  CHECK(dataset.sampleCount() == 6);
  CHECK(dataset.probeCount() == 2);
  CHECK(dataset.sample(5).position == glm::vec3(3.5f, 2.5f, 1.2f));
  for (int i = 0; i < dataset.probeCount(); ++i) {
    const glm::vec3 p = dataset.probe(i).position;
    CHECK(p.x >= 0.5f);
    CHECK(p.x <= 3.5f);
    CHECK(p.y >= 0.5f);
    CHECK(p.y <= 2.5f);
  }
  CHECK(testing::countEntries(directory.path(), "box.partial-triwalk") == 0);
  // What a decimation reads, kept as each view was written: at 64x32 the
  // error width is the data set's, so the samples' simplified meshes and no
  // downsampled copies (core/selection/selection_inputs.h).
  const SimplifiedMeshStore meshes(dataset);
  for (int i = 0; i < dataset.sampleCount(); ++i) {
    CHECK(std::filesystem::is_regular_file(meshes.file(dataset.sample(i), 64, WarpOptions{}.meshTolerancePixels)));
  }
  CHECK_FALSE(std::filesystem::exists(meshes.file(dataset.probe(0), 64, WarpOptions{}.meshTolerancePixels)));
  CHECK_FALSE(std::filesystem::exists(directory / "box" / "downsampled"));

  std::filesystem::create_directories(directory / "other");
  std::ofstream(directory / "other/notes.txt") << "keep me";
  testing::requireInputError([&] { captureDataset(scene, "box", options, directory / "other"); },
                             (directory / "other").string(), "not a triwalk data set");
  CHECK(std::filesystem::exists(directory / "other/notes.txt"));
}

TEST_CASE("door leaves are open in captures unless asked closed, and the manifest says which") {
  testing::TemporaryDirectory directory;
  auto context = createHeadlessContext();
  // The box with a door leaf across it at x = 2; the samples stand before it.
  Scene scene = boxRoom();
  SceneMaterial door;
  door.baseColor = glm::vec3(0.5f);
  door.passable = true;
  scene.materials.push_back(door);
  MeshBuilder builder(int(scene.materials.size()) - 1, 1.0f);
  builder.addQuad({2.0f, 0.0f, 0.0f}, {0.0f, 3.0f, 0.0f}, {0.0f, 0.0f, 2.5f}, 0.5f);
  scene.meshes.push_back(builder.take());
  CaptureOptions options;
  options.area = glm::vec4(0.5f, 0.5f, 1.5f, 2.5f);
  options.paths = 2;
  options.perPath = 2;
  options.width = 64;
  options.probes = 0;
  options.quiet = true;
  // The farthest surface seen towards +x: the far wall (x = 4) through an
  // open door, the leaf (x = 2) when it is closed.
  auto farthestAhead = [](const Dataset& dataset) {
    float farthest = 0.0f;
    for (int i = 0; i < dataset.sampleCount(); ++i) {
      const Panorama panorama = dataset.loadView(dataset.sample(i));
      const EquirectProjection projection = dataset.projection(dataset.sample(i));
      for (int v = 0; v < panorama.height(); ++v) {
        for (int u = 0; u < panorama.width(); ++u) {
          const glm::vec3 direction = projection.pixelDirection(u, v);
          if (direction.x > 0.95f) farthest = std::max(farthest, direction.x * panorama.distance.at(u, v));
        }
      }
    }
    return farthest;
  };
  captureDataset(scene, "box with a door", options, directory / "open");
  const Dataset open = Dataset::open(directory / "open");
  CHECK(open.manifest().capture.at("doors") == "open");
  CHECK(farthestAhead(open) == doctest::Approx(4.0f - 0.5f).epsilon(0.02));
  options.closedDoors = true;
  captureDataset(scene, "box with a door", options, directory / "closed");
  const Dataset closed = Dataset::open(directory / "closed");
  CHECK(closed.manifest().capture.at("doors") == "closed");
  CHECK(farthestAhead(closed) == doctest::Approx(2.0f - 0.5f).epsilon(0.02));
  // A scene without doors does not mention them.
  options.closedDoors = false;
  captureDataset(boxRoom(), "box", options, directory / "box");
  CHECK_FALSE(Dataset::open(directory / "box").manifest().capture.contains("doors"));
}

}  // namespace triwalk
