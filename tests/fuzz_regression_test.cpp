// Inputs the fuzzers (fuzz/) once crashed or hung a reader with: each must
// now be read, or refused with an InputError that names the file, as any
// bad input is; any other exception fails.

#include "core/geometry/walkable_region.h"
#include "core/import/pose_table.h"
#include "core/io/camera_path_file.h"
#include "core/io/dataset.h"
#include "core/io/exr_io.h"
#include "core/io/json_fields.h"
#include "core/selection/selection.h"
#include "fuzz/numeric_drive.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <cmath>

#include <functional>
#include <map>

namespace triwalk {

TEST_CASE("inputs that crashed or hung a fuzzer are read or refused with a one-line error") {
  const std::filesystem::path root = std::filesystem::path(TRIWALK_SOURCE_DIR) / "fuzz";
  const std::filesystem::path seedDataset = root / "seeds/dataset";
  testing::TemporaryDirectory directory;
  std::filesystem::copy(seedDataset, directory / "dataset", std::filesystem::copy_options::recursive);
  const Dataset dataset = Dataset::open(seedDataset);

  // Each reader as its harness calls it, on a copy of the input named as
  // the reader expects.
  const std::map<std::string, std::function<std::filesystem::path(const std::filesystem::path&)>> readers = {
      {"manifest", [&](const std::filesystem::path& input) {
         const std::filesystem::path manifest = directory / "dataset" / kManifestFileName;
         std::filesystem::copy_file(input, manifest, std::filesystem::copy_options::overwrite_existing);
         Dataset::open(directory / "dataset");
         return manifest;
       }},
      {"exr", [](const std::filesystem::path& input) { readPanoramaExr(input); return input; }},
      {"selection", [&](const std::filesystem::path& input) { readSelection(input, dataset); return input; }},
      {"camera_path", [](const std::filesystem::path& input) {
         // Read, then played as the harness plays it: every frame's pose finite.
         const CameraPath path = readCameraPath(input);
         if (frameCount(path, 30.0) <= 10000) {
           for (const CameraPose& pose : framePoses(path, 30.0)) {
             CHECK(std::isfinite(pose.position.x + pose.position.y + pose.position.z + pose.yawDegrees + pose.pitchDegrees));
           }
         }
         return input;
       }},
      {"pose_table", [](const std::filesystem::path& input) {
         readPoseTable(input, PoseMatrix::WorldToCamera, UpAxis::PlusY);
         return input;
       }},
      {"region", [](const std::filesystem::path& input) {
         const WalkableRegion region = WalkableRegion::fromJson(readJsonFile(input), input.string());
         glm::dvec2 low, high;
         region.bounds(low, high);
         const std::vector<glm::dvec2> samples = {low, high, {low.x, high.y}};
         CHECK(sampleAreaWeights(samples, region).size() == 3);
         return input;
       }},
  };
  size_t inputs = 0;
  for (const auto& [reader, read] : readers) {
    const std::filesystem::path folder = root / "regressions" / reader;
    if (!std::filesystem::exists(folder)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      CAPTURE(entry.path());
      const std::string subject = reader == "manifest" ? std::string(kManifestFileName) : entry.path().filename().string();
      try {
        read(entry.path());
      } catch (const InputError& error) {
        CHECK(std::string(error.what()).find(subject) != std::string::npos);
      }
      ++inputs;
    }
  }
  CHECK(inputs >= 1);
}


TEST_CASE("the numeric harness's corpus: each input refused in one line or driven through decimate and eval, finite") {
  // fuzz/seeds/numeric is the harness's corpus after its runs, merged to
  // the inputs that reach new code (docs/RELIABILITY.md, "Fuzzing"); a
  // crash, an exception other than InputError or a non-finite error aborts.
  const std::filesystem::path root = std::filesystem::path(TRIWALK_SOURCE_DIR) / "fuzz";
  testing::TemporaryDirectory scratch;
  size_t driven = 0, refused = 0;
  for (const char* folder : {"seeds/numeric", "regressions/numeric"}) {
    if (!std::filesystem::exists(root / folder)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
      CAPTURE(entry.path());
      const std::string bytes = testing::readTextFileOrEmpty(entry.path());
      const bool accepted = fuzz::driveNumbers(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(),
                                               root / "seeds/dataset", scratch.path());
      (accepted ? driven : refused) += 1;
    }
  }
  MESSAGE(driven << " inputs driven through, " << refused << " refused");
  CHECK(driven >= 10);
  CHECK(refused >= 10);
}

TEST_CASE("EXR headers claiming more than the file holds are refused before OpenEXR allocates for them") {
  // OpenEXR would allocate and clear the claimed sizes first (seconds under
  // the sanitizers); the checks name what is wrong instead.
  const std::filesystem::path inputs = std::filesystem::path(TRIWALK_SOURCE_DIR) / "fuzz/regressions/exr";
  CHECK_THROWS_WITH_AS(readPanoramaExr(inputs / "attribute-size-past-end"),
                       doctest::Contains("claims 1852402688 bytes but the file has 4 left"), InputError);
  // A second dataWindow attribute with a huge window: OpenEXR sizes its
  // per-line tables from it.
  CHECK_THROWS_WITH_AS(readPanoramaExr(inputs / "data-window-lines"),
                       doctest::Contains("size 1836016384x1936028272 is larger than triwalk reads"), InputError);
}

}  // namespace triwalk
