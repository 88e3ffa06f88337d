// Real scenes through Assimp: the furnished house (IFC) and a Quake 3
// level (.pk3) from Debian's packages, and bad scene files.

#include "core/support/errors.h"
#include "render/capture/panorama_capturer.h"
#include "render/capture/walkable_area.h"
#include "render/gl/gl_context.h"
#include "scene/assimp_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>

namespace triwalk {

namespace {

const std::filesystem::path kHouse = "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc";
const std::filesystem::path kLevels = "/usr/share/games/openarena/baseoa/z_oacmp-volume1-v3.pk3";

}  // namespace

TEST_CASE("the IFC house loads with its triangles, in metres, z up") {
  REQUIRE_MESSAGE(std::filesystem::exists(kHouse), "install assimp-testmodels (scripts/install-deps.sh test)");
  SceneImportReport report;
  const Scene scene = importScene(kHouse, SceneImportOptions{}, report);
  CHECK(scene.triangleCount() == 35906);
  glm::vec3 lower, upper;
  scene.bounds(lower, upper);
  // Assimp gives the IFC model y up; triwalk turns it z up: (x, y, z) -> (x, -z, y).
  CHECK(lower.x == doctest::Approx(-3.0).epsilon(0.01));
  CHECK(upper.x == doctest::Approx(15.0).epsilon(0.01));
  CHECK(lower.y == doctest::Approx(-3.0).epsilon(0.01));
  CHECK(upper.y == doctest::Approx(13.0).epsilon(0.01));
  CHECK(lower.z == doctest::Approx(-1.0).epsilon(0.01));
  CHECK(upper.z == doctest::Approx(6.32).epsilon(0.01));
  // The ground floor is the largest horizontal surface, at z = 0.
  CHECK(std::abs(dominantFloorHeight(scene)) < 0.06f);
}

TEST_CASE("the house's automatic region: its ground floor from room to room, every sample enclosed with a floor below") {
  REQUIRE(std::filesystem::exists(kHouse));
  SceneImportReport report;
  const Scene scene = importScene(kHouse, SceneImportOptions{}, report);
  auto context = createHeadlessContext();
  const WalkableRegionProposal proposal = proposeWalkableRegion(scene, {}, kHouse.string());
  INFO(proposal.reason);
  CHECK(proposal.floorZ == doctest::Approx(0.0).epsilon(0.06));
  CHECK(proposal.region.area() >= 40.0);
  CHECK(proposal.parts == 1);
  // A point in the middle of the region's first outer ring's bounds may be
  // in a wall; its walkable cells are not: the first probe in the region.
  glm::dvec2 lower, upper;
  proposal.region.bounds(lower, upper);
  PanoramaCapturer capturer(scene, 128);
  int checked = 0;
  for (double y = lower.y + 0.125; y < upper.y && checked < 3; y += 1.0) {
    for (double x = lower.x + 0.125; x < upper.x && checked < 3; x += 1.0) {
      if (!proposal.region.contains({x, y})) continue;
      const Panorama panorama = capturer.capture(glm::vec3(x, y, proposal.floorZ + 1.6f));
      size_t infinite = 0;
      for (float d : panorama.distance.pixels) infinite += !std::isfinite(d);
      CHECK(infinite < panorama.distance.pixelCount() / 20);
      CHECK(panorama.distance.at(64, 63) == doctest::Approx(1.6).epsilon(0.05));  // straight down: the floor
      ++checked;
    }
  }
  CHECK(checked == 3);
}

TEST_CASE("zero-area triangles of the house leave no NaN in a capture") {
  // From this position (sample 29 of the automatic area) llvmpipe
  // rasterizes a few fragments of a zero-area triangle with NaN
  // interpolated positions; they used to shade to NaN colours, which the
  // EXR writer refuses.
  REQUIRE(std::filesystem::exists(kHouse));
  SceneImportReport report;
  const Scene scene = importScene(kHouse, SceneImportOptions{}, report);
  auto context = createHeadlessContext();
  PanoramaCapturer capturer(scene, 1024);
  const Panorama panorama = capturer.capture({4.25f + 2.0f / 14.0f * 14.0f, 0.75f + 4.5f / 29.0f, 1.6f});
  size_t nonFinite = 0;
  for (const glm::vec3& color : panorama.color.pixels) nonFinite += !std::isfinite(color.r + color.g + color.b);
  CHECK(nonFinite == 0);
}

TEST_CASE("the Quake 3 level oacmpdm3 loads by name with its textures, lightmaps and spawn points") {
  REQUIRE_MESSAGE(std::filesystem::exists(kLevels), "install openarena-oacmp1 (scripts/install-deps.sh test)");
  SceneImportOptions options;
  options.map = "oacmpdm3";
  SceneImportReport report;
  const Scene scene = importScene(kLevels, options, report);
  CHECK(report.map == "oacmpdm3");
  CHECK(scene.triangleCount() > 5000);
  CHECK(report.texturesLoaded > 100);
  CHECK(report.missingTextures.size() < 10);
  CHECK(report.spawnPoints.size() == 27);
  int textured = 0, lightmapped = 0;
  for (const SceneMaterial& material : scene.materials) {
    textured += material.diffuseTexture >= 0;
    lightmapped += material.lightmapTexture >= 0;
  }
  CHECK(textured > int(scene.materials.size()) * 8 / 10);
  CHECK(lightmapped > int(scene.materials.size()) / 2);
  // Quake 3 units are inches: the level spans tens of metres, not thousands.
  glm::vec3 lower, upper;
  scene.bounds(lower, upper);
  CHECK(upper.x - lower.x < 200.0f);
  CHECK(upper.x - lower.x > 10.0f);
}

TEST_CASE("bad scene files give a one-line error naming the file") {
  testing::TemporaryDirectory directory;
  SceneImportReport report;
  testing::requireInputError([&] { importScene(directory / "missing.obj", SceneImportOptions{}, report); },
                             "missing.obj", "does not exist");
  std::ofstream(directory / "corrupt.obj") << "v 1 2\nf 1 2 3 4 5\nthis is not a mesh\n";
  testing::requireInputError([&] { importScene(directory / "corrupt.obj", SceneImportOptions{}, report); },
                             "corrupt.obj", "cannot import scene");
  std::ofstream(directory / "scene.xyz") << "nothing Assimp knows";
  testing::requireInputError([&] { importScene(directory / "scene.xyz", SceneImportOptions{}, report); }, "scene.xyz",
                             "cannot import scene");
  std::ofstream(directory / "broken.pk3") << "PK not really a zip";
  testing::requireInputError([&] { importScene(directory / "broken.pk3", SceneImportOptions{}, report); }, "broken.pk3",
                             "not a readable zip");
  if (std::filesystem::exists(kLevels)) {
    SceneImportOptions options;
    options.map = "nosuchmap";
    testing::requireInputError([&] { importScene(kLevels, options, report); }, kLevels.string(), "no map 'nosuchmap'");
  }
}

}  // namespace triwalk
