// Camera path files: exact round trip, and one error per kind of bad line.

#include "core/io/atomic_file.h"
#include "core/io/camera_path.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

namespace triwalk {

TEST_CASE("camera path round trip keeps every pose, and comments and blank lines are skipped") {
  testing::TemporaryDirectory directory;
  const std::vector<CameraPose> poses = {{{1.5f, -2.25f, 1.6f}, 90.0f, -10.0f}, {{0.0f, 0.0f, 1.0f}, -45.5f, 89.0f}};
  writeCameraPath(directory / "path.txt", poses);
  writeTextFileAtomically(directory / "path.txt", readTextFile(directory / "path.txt") + "\n   \n# the end\n");
  const std::vector<CameraPose> read = readCameraPath(directory / "path.txt");
  REQUIRE(read.size() == 2);
  for (size_t i = 0; i < poses.size(); ++i) {
    CHECK(read[i].position == poses[i].position);
    CHECK(read[i].yawDegrees == poses[i].yawDegrees);
    CHECK(read[i].pitchDegrees == poses[i].pitchDegrees);
  }
}

TEST_CASE("bad camera paths give one-line errors naming the file and the line") {
  testing::TemporaryDirectory directory;
  const std::filesystem::path file = directory / "path.txt";
  auto read = [&](const std::string& text) {
    writeTextFileAtomically(file, text);
    return [&] { readCameraPath(file); };
  };
  testing::requireInputError([&] { readCameraPath(directory / "missing.txt"); }, "missing.txt", "file does not exist");
  testing::requireInputError(read("# only a comment\n"), file.string(), "no poses in the camera path");
  testing::requireInputError(read("0 0 1.6 0 0\n1 2 3\n"), file.string(), "line 2: expected 'x y z yaw pitch'");
  testing::requireInputError(read("0 0 1.6 0 0 7\n"), file.string(), "line 1: expected 'x y z yaw pitch'");
  testing::requireInputError(read("0 zero 1.6 0 0\n"), file.string(), "line 1: expected 'x y z yaw pitch'");
  testing::requireInputError(read("0 0 1.6 0 90\n"), file.string(), "line 1: values must be finite, |pitch| < 90");
  testing::requireInputError(read("0 0 1e39 0 0\n"), file.string(), "line 1");
}

}  // namespace triwalk
