// Real scenes through Assimp: the furnished house (IFC) and a Quake 3
// level (.pk3) from Debian's packages, and bad scene files.

#include "core/support/errors.h"
#include "render/capture/panorama_capturer.h"
#include "render/capture/walkable_area.h"
#include "render/gl/gl_context.h"
#include "render/scene/assimp_scene.h"
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
  ImportReport report;
  const Scene scene = importScene(kHouse, ImportOptions{}, report);
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

TEST_CASE("inside a room of the house, every direction meets a surface; the automatic area lies inside") {
  REQUIRE(std::filesystem::exists(kHouse));
  ImportReport report;
  const Scene scene = importScene(kHouse, ImportOptions{}, report);
  auto context = createHeadlessContext();
  const WalkableAreaProposal proposal = proposeWalkableArea(scene, 1.6f, 0.5f, kHouse.string());
  INFO(proposal.reason);
  CHECK(proposal.area.z - proposal.area.x >= 1.5f);
  CHECK(proposal.area.w - proposal.area.y >= 1.5f);
  PanoramaCapturer capturer(scene, 128);
  const glm::vec3 inside(0.5f * (proposal.area.x + proposal.area.z), 0.5f * (proposal.area.y + proposal.area.w),
                         proposal.floorZ + 1.6f);
  const Panorama panorama = capturer.capture(inside);
  size_t infinite = 0;
  for (float d : panorama.distance.pixels) infinite += !std::isfinite(d);
  CHECK(infinite == 0);
  // Straight down is the floor at eye height.
  CHECK(panorama.distance.at(64, 63) == doctest::Approx(1.6).epsilon(0.02));
}

TEST_CASE("zero-area triangles of the house leave no NaN in a capture") {
  // From this position (sample 29 of the automatic area) llvmpipe
  // rasterizes a few fragments of a zero-area triangle with NaN
  // interpolated positions; they used to shade to NaN colours, which the
  // EXR writer refuses.
  REQUIRE(std::filesystem::exists(kHouse));
  ImportReport report;
  const Scene scene = importScene(kHouse, ImportOptions{}, report);
  auto context = createHeadlessContext();
  PanoramaCapturer capturer(scene, 1024);
  const Panorama panorama = capturer.capture({4.25f + 2.0f / 14.0f * 14.0f, 0.75f + 4.5f / 29.0f, 1.6f});
  size_t nonFinite = 0;
  for (const glm::vec3& color : panorama.color.pixels) nonFinite += !std::isfinite(color.r + color.g + color.b);
  CHECK(nonFinite == 0);
}

TEST_CASE("the Quake 3 level oacmpdm3 loads by name with its textures, lightmaps and spawn points") {
  REQUIRE_MESSAGE(std::filesystem::exists(kLevels), "install openarena-oacmp1 (scripts/install-deps.sh test)");
  ImportOptions options;
  options.map = "oacmpdm3";
  ImportReport report;
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
  ImportReport report;
  testing::requireInputError([&] { importScene(directory / "missing.obj", ImportOptions{}, report); }, "missing.obj",
                             "does not exist");
  std::ofstream(directory / "corrupt.obj") << "v 1 2\nf 1 2 3 4 5\nthis is not a mesh\n";
  testing::requireInputError([&] { importScene(directory / "corrupt.obj", ImportOptions{}, report); }, "corrupt.obj",
                             "cannot import scene");
  std::ofstream(directory / "scene.xyz") << "nothing Assimp knows";
  testing::requireInputError([&] { importScene(directory / "scene.xyz", ImportOptions{}, report); }, "scene.xyz",
                             "cannot import scene");
  std::ofstream(directory / "broken.pk3") << "PK not really a zip";
  testing::requireInputError([&] { importScene(directory / "broken.pk3", ImportOptions{}, report); }, "broken.pk3",
                             "not a readable zip");
  if (std::filesystem::exists(kLevels)) {
    ImportOptions options;
    options.map = "nosuchmap";
    testing::requireInputError([&] { importScene(kLevels, options, report); }, kLevels.string(), "no map 'nosuchmap'");
  }
}

}  // namespace triwalk
