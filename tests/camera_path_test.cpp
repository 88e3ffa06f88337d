// Camera paths: exact file round trips (one pose a frame, and recorded
// walks with their times), one error per kind of bad line, and the
// playback's curve: through every pose, never past one, still in a pause,
// turning the short way.

#include "core/geometry/camera_path.h"
#include "core/io/atomic_file.h"
#include "core/io/camera_path_file.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

namespace triwalk {

namespace {

void requireSamePoses(const std::vector<CameraPose>& read, const std::vector<CameraPose>& written) {
  REQUIRE(read.size() == written.size());
  for (size_t i = 0; i < written.size(); ++i) {
    CHECK(read[i].position == written[i].position);
    CHECK(read[i].yawDegrees == written[i].yawDegrees);
    CHECK(read[i].pitchDegrees == written[i].pitchDegrees);
  }
}

// A walk of four poses: a zig-zag in x and y, turning through north (yaw
// 350 -> 10), with a pause (poses 2 and 3 equal).
CameraPath zigZagWalk() {
  CameraPath path;
  path.poses = {{{0.0f, 0.0f, 1.6f}, 340.0f, 0.0f},
                {{1.0f, 1.0f, 1.6f}, 350.0f, 10.0f},
                {{2.0f, 0.0f, 1.6f}, 10.0f, -5.0f},
                {{2.0f, 0.0f, 1.6f}, 10.0f, -5.0f},
                {{3.0f, 2.0f, 1.6f}, 40.0f, 0.0f}};
  path.seconds = {2.0, 2.5, 3.5, 4.5, 4.75};
  return path;
}

}  // namespace

TEST_CASE("camera path round trip keeps every pose, and comments and blank lines are skipped") {
  testing::TemporaryDirectory directory;
  CameraPath path;
  path.poses = {{{1.5f, -2.25f, 1.6f}, 90.0f, -10.0f}, {{0.0f, 0.0f, 1.0f}, -45.5f, 89.0f}};
  writeCameraPath(directory / "path.txt", path);
  writeTextFileAtomically(directory / "path.txt", readTextFile(directory / "path.txt") + "\n   \n# the end\n");
  const CameraPath read = readCameraPath(directory / "path.txt");
  CHECK_FALSE(read.timed());
  requireSamePoses(read.poses, path.poses);
}

TEST_CASE("a recorded walk's times round trip to the microsecond") {
  testing::TemporaryDirectory directory;
  CameraPath path = zigZagWalk();
  path.seconds = {0.0, 0.033333, 1.0 / 15.0, 12.5, 3600.000001};
  writeCameraPath(directory / "walk.txt", path);
  const CameraPath read = readCameraPath(directory / "walk.txt");
  REQUIRE(read.timed());
  requireSamePoses(read.poses, path.poses);
  for (size_t i = 0; i < path.seconds.size(); ++i) CHECK(std::abs(read.seconds[i] - path.seconds[i]) <= 0.5e-6);
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
  testing::requireInputError(read("0 0 1.6 0 0\n1 2 3\n"), file.string(), "line 2: expected 'x y z yaw pitch [seconds]'");
  testing::requireInputError(read("0 0 1.6 0 0 7 8\n"), file.string(), "line 1: expected 'x y z yaw pitch [seconds]'");
  testing::requireInputError(read("0 0 1.6 0 0 seven\n"), file.string(), "line 1: expected 'x y z yaw pitch [seconds]'");
  testing::requireInputError(read("0 zero 1.6 0 0\n"), file.string(), "line 1: expected 'x y z yaw pitch [seconds]'");
  testing::requireInputError(read("0 0 1.6 0 90\n"), file.string(), "line 1: values must be finite");
  testing::requireInputError(read("0 0 1e39 0 0\n"), file.string(), "line 1");
  testing::requireInputError(read("2e7 0 1.6 0 0\n"), file.string(), "line 1: values must be finite, |x|, |y|, |z| <= 1e7 m");
  testing::requireInputError(read("0 0 1.6 0 0 nan\n"), file.string(), "line 1: expected");
  testing::requireInputError(read("0 0 1.6 0 0 -1\n"), file.string(), "line 1: values must be finite");
  testing::requireInputError(read("0 0 1.6 0 0 0\n1 0 1.6 0 0\n"), file.string(),
                             "line 2: seconds must be given on every line or on none");
  testing::requireInputError(read("0 0 1.6 0 0\n1 0 1.6 0 0 1\n"), file.string(),
                             "line 2: seconds must be given on every line or on none");
  testing::requireInputError(read("0 0 1.6 0 0 1\n1 0 1.6 0 0 1\n"), file.string(),
                             "line 2: seconds must increase from line to line");
}

TEST_CASE("the playback passes through every pose at its time, and one pose a frame at the frame rate") {
  const CameraPath walk = zigZagWalk();
  CHECK(pathDuration(walk, 30.0) == doctest::Approx(2.75));
  for (size_t i = 0; i < walk.poses.size(); ++i) {
    const CameraPose pose = poseAt(walk, walk.seconds[i] - walk.seconds.front(), 30.0);
    CHECK(glm::distance(pose.position, walk.poses[i].position) < 1e-5f);
    CHECK(pose.yawDegrees == doctest::Approx(walk.poses[i].yawDegrees));
    CHECK(pose.pitchDegrees == doctest::Approx(walk.poses[i].pitchDegrees));
  }
  // Before the start and after the end: the ends.
  CHECK(poseAt(walk, -1.0, 30.0).position == walk.poses.front().position);
  CHECK(poseAt(walk, 99.0, 30.0).position == walk.poses.back().position);

  CameraPath frames;
  frames.poses = walk.poses;
  CHECK(pathDuration(frames, 10.0) == doctest::Approx(0.4));
  for (size_t i = 0; i < frames.poses.size(); ++i) {
    CHECK(glm::distance(poseAt(frames, double(i) / 10.0, 10.0).position, frames.poses[i].position) < 1e-5f);
  }
  const std::vector<CameraPose> same = framePoses(frames, 10.0);
  requireSamePoses(same, frames.poses);
}

TEST_CASE("between two poses the playback stays between them, still in a pause, and turns the short way") {
  const CameraPath walk = zigZagWalk();
  for (size_t i = 0; i + 1 < walk.poses.size(); ++i) {
    const CameraPose& a = walk.poses[i];
    const CameraPose& b = walk.poses[i + 1];
    for (int step = 1; step < 50; ++step) {
      const double t = walk.seconds[i] - walk.seconds.front() + (walk.seconds[i + 1] - walk.seconds[i]) * step / 50.0;
      const CameraPose pose = poseAt(walk, t, 30.0);
      INFO("segment " << i << ", step " << step);
      for (int c = 0; c < 3; ++c) {
        CHECK(pose.position[c] >= std::min(a.position[c], b.position[c]) - 1e-5f);
        CHECK(pose.position[c] <= std::max(a.position[c], b.position[c]) + 1e-5f);
      }
      CHECK(pose.pitchDegrees >= std::min(a.pitchDegrees, b.pitchDegrees) - 1e-4f);
      CHECK(pose.pitchDegrees <= std::max(a.pitchDegrees, b.pitchDegrees) + 1e-4f);
      if (i == 2) CHECK(glm::distance(pose.position, a.position) < 1e-6f);  // the pause
      // 350 -> 10 goes through 0, never through 180.
      if (i == 1) CHECK((pose.yawDegrees >= 350.0f - 1e-3f || pose.yawDegrees <= 10.0f + 1e-3f));
      CHECK(pose.yawDegrees >= 0.0f);
      CHECK(pose.yawDegrees < 360.0f);
    }
  }
  // Smooth, not a polyline: half way along the first segment the curve
  // leaves the straight line between its poses' times (its speed changes).
  const CameraPose half = poseAt(walk, 0.25, 30.0);
  CHECK(std::abs(half.position.x - 0.5f) > 1e-3f);
}

TEST_CASE("a recorded walk's frames at a frame rate: every 1/fps seconds, its end included") {
  const CameraPath walk = zigZagWalk();  // 2.75 s
  CHECK(frameCount(walk, 4.0) == 12);  // 0, 0.25, ..., 2.75
  const std::vector<CameraPose> atFour = framePoses(walk, 4.0);
  REQUIRE(atFour.size() == 12);
  CHECK(atFour.back().position == walk.poses.back().position);
  CHECK(glm::distance(atFour[2].position, walk.poses[1].position) < 1e-5f);  // 0.5 s
  CHECK(frameCount(walk, 3.0) == 10);  // 0 .. 2.667 every third of a second, then the end at 2.75
  CHECK(framePoses(walk, 3.0).back().position == walk.poses.back().position);
}

TEST_CASE("recording keeps a pause as its first and last pose and skips frames within a millisecond") {
  CameraPath path;
  const CameraPose here{{1.0f, 2.0f, 1.6f}, 30.0f, 0.0f}, there{{1.5f, 2.0f, 1.6f}, 30.0f, 0.0f};
  appendRecordedPose(path, here, 0.0);
  appendRecordedPose(path, here, 0.0005);  // within a millisecond: skipped
  appendRecordedPose(path, here, 0.1);
  appendRecordedPose(path, here, 0.2);
  appendRecordedPose(path, here, 0.3);
  appendRecordedPose(path, there, 0.4);
  REQUIRE(path.poses.size() == 3);
  CHECK(path.seconds == std::vector<double>{0.0, 0.3, 0.4});
  CHECK(poseAt(path, 0.15, 30.0).position == here.position);
  CHECK(poseAt(path, 0.4, 30.0).position == there.position);
}

}  // namespace triwalk
