// The viewer, run as a person would start it, under a virtual X server
// (xvfb-run): a few frames of a small data set, then its screenshot must
// show the walkthrough and the panels.

#include "core/io/png_io.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <set>

namespace triwalk {

TEST_CASE("the viewer under Xvfb shows the scene and its panels") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 256, 1);
  const std::filesystem::path screenshot = directory / "viewer.png";
  const std::string command = std::string("xvfb-run -a -s '-screen 0 1280x800x24' ") + TRIWALK_BINARY +
                              " view --dataset " + (directory / "data").string() + " --frames 8 --screenshot " +
                              screenshot.string() + " > " + (directory / "log.txt").string() + " 2>&1";
  const int status = std::system(command.c_str());
  INFO("log: " << testing::readTextFileOrEmpty(directory / "log.txt"));
  REQUIRE(status == 0);
  REQUIRE(std::filesystem::exists(screenshot));
  const Rgb8Image image = readPng(screenshot);
  CHECK(image.width == 1280);
  CHECK(image.height == 720);

  // The walkthrough, right of the panels: the room's smooth colors, not
  // the single clear color of an empty frame.
  std::set<uint32_t> sceneColors;
  for (int y = 620; y < 715; ++y) {
    for (int x = 1020; x < 1275; ++x) {
      const glm::u8vec3 c = image.at(x, y);
      sceneColors.insert(uint32_t(c.r) << 16 | uint32_t(c.g) << 8 | c.b);
    }
  }
  CHECK(sceneColors.size() > 200);

  // The map panel: its background (25, 25, 30) fills most of its canvas,
  // with the triangulation drawn over it.
  size_t mapBackground = 0;
  for (int y = 40; y < 280; ++y) {
    for (int x = 20; x < 420; ++x) mapBackground += image.at(x, y) == glm::u8vec3(25, 25, 30);
  }
  CHECK(mapBackground > 2000);
}

}  // namespace triwalk
