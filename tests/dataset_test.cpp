// Data set format: exact round trips and one clear error per kind of bad input.

#include "core/io/dataset.h"
#include "core/io/exr_io.h"
#include "core/io/json_fields.h"
#include "tests/test_support.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <half.h>

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>

namespace triwalk {

using testing::requireInputError;
using testing::TemporaryDirectory;

namespace {

// Colors that half represents exactly, distances with +inf for sky.
Panorama syntheticPanorama(int width, int height, unsigned seed) {
  std::mt19937 engine(seed);
  Panorama panorama{ColorImage(width, height), ScalarImage(width, height)};
  for (size_t i = 0; i < panorama.color.pixelCount(); ++i) {
    const float r = float(half(float(engine() % 1000) / 997.0f));
    const float g = float(half(float(engine() % 1000) / 311.0f));
    const float b = float(half(float(engine() % 1000) / 1999.0f));
    panorama.color.pixels[i] = {r, g, b};
    panorama.distance.pixels[i] = i % 7 == 0 ? std::numeric_limits<float>::infinity()
                                             : 0.25f + float(engine() % 100000) / 3.0f;
  }
  return panorama;
}

Manifest syntheticManifest(int width, int sampleCount) {
  Manifest manifest;
  manifest.scene = "synthetic";
  manifest.width = width;
  manifest.height = width / 2;
  for (int i = 0; i < sampleCount; ++i) {
    ViewRecord sample;
    sample.id = i;
    sample.file = "samples/s" + std::to_string(i) + ".exr";
    sample.position = {float(i % 2), float(i / 2) + 0.25f * float(i % 2), 1.5f};
    sample.path = i % 2;
    sample.step = i / 2;
    manifest.samples.push_back(sample);
  }
  ViewRecord probe;
  probe.id = 0;
  probe.file = "probes/p0.exr";
  probe.position = {0.4f, 0.3f, 1.5f};
  manifest.probes.push_back(probe);
  return manifest;
}

void writeDataset(const std::filesystem::path& directory, const Manifest& manifest) {
  std::filesystem::create_directories(directory / "samples");
  std::filesystem::create_directories(directory / "probes");
  unsigned seed = 1;
  for (const auto* views : {&manifest.samples, &manifest.probes}) {
    for (const ViewRecord& view : *views) {
      writePanoramaExr(directory / view.file, syntheticPanorama(manifest.width, manifest.height, seed++));
    }
  }
  writeManifest(directory, manifest);
}

// Edits manifest.json as JSON, bypassing writeManifest's validation.
void editManifest(const std::filesystem::path& directory, const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json document = readJsonFile(directory / kManifestFileName);
  edit(document);
  writeJsonFile(directory / kManifestFileName, document);
}

void writeExrWithChannels(const std::filesystem::path& path, int width, int height, const std::vector<std::string>& names,
                          float distanceValue) {
  Imf::Header header(width, height);
  std::vector<std::vector<float>> planes;
  Imf::FrameBuffer frameBuffer;
  for (const std::string& name : names) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  planes.reserve(names.size());
  for (const std::string& name : names) {
    planes.emplace_back(size_t(width * height), name == "Z" ? distanceValue : 0.5f);
    frameBuffer.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(planes.back().data()), sizeof(float),
                                        sizeof(float) * size_t(width)));
  }
  Imf::OutputFile file(path.string().c_str(), header);
  file.setFrameBuffer(frameBuffer);
  file.writePixels(height);
}

}  // namespace

TEST_CASE("OpenEXR panorama round trip is exact, including +inf distance") {
  TemporaryDirectory directory;
  const Panorama original = syntheticPanorama(64, 32, 7);
  writePanoramaExr(directory / "view.exr", original);
  const Panorama loaded = readPanoramaExr(directory / "view.exr");
  REQUIRE(loaded.width() == 64);
  REQUIRE(loaded.height() == 32);
  CHECK(loaded.color.pixels == original.color.pixels);
  size_t infinite = 0;
  for (size_t i = 0; i < original.distance.pixelCount(); ++i) {
    CHECK(loaded.distance.pixels[i] == original.distance.pixels[i]);
    infinite += std::isinf(loaded.distance.pixels[i]);
  }
  CHECK(infinite > 0);
  // The temporary file of the atomic write is gone.
  CHECK(std::distance(std::filesystem::directory_iterator(directory.path()), {}) == 1);
}

TEST_CASE("a view whose colour half cannot hold is refused and nothing is written") {
  TemporaryDirectory directory;
  for (const float bad : {std::nanf(""), 1.0e6f}) {
    Panorama panorama = syntheticPanorama(16, 8, 3);
    panorama.color.pixels[5 * 16 + 3].g = bad;
    requireInputError([&] { writePanoramaExr(directory / "view.exr", panorama); }, "view.exr",
                      "out-of-range color at pixel 3,5");
    CHECK(std::filesystem::is_empty(directory.path()));
  }
}

TEST_CASE("data set round trip: manifest fields and views survive write and open") {
  TemporaryDirectory directory;
  const Manifest manifest = syntheticManifest(32, 5);
  writeDataset(directory.path(), manifest);
  const Dataset dataset = Dataset::open(directory.path());
  REQUIRE(dataset.sampleCount() == 5);
  REQUIRE(dataset.probeCount() == 1);
  CHECK(dataset.manifest().scene == "synthetic");
  CHECK(dataset.manifest().width == 32);
  CHECK(dataset.manifest().height == 16);
  for (int i = 0; i < 5; ++i) {
    CHECK(dataset.sample(i).id == manifest.samples[size_t(i)].id);
    CHECK(dataset.sample(i).file == manifest.samples[size_t(i)].file);
    CHECK(dataset.sample(i).position == manifest.samples[size_t(i)].position);
    CHECK(dataset.sample(i).path == manifest.samples[size_t(i)].path);
    CHECK(dataset.sample(i).step == manifest.samples[size_t(i)].step);
  }
  CHECK(dataset.probe(0).position == manifest.probes[0].position);
  const Panorama loaded = dataset.loadView(dataset.sample(2));
  CHECK(loaded.color.pixels == syntheticPanorama(32, 16, 3).color.pixels);
}

TEST_CASE("bad data sets give one-line errors naming the file") {
  TemporaryDirectory directory;
  const std::filesystem::path root = directory.path();
  writeDataset(root, syntheticManifest(32, 4));
  const std::string manifestName = (root / kManifestFileName).string();
  auto open = [&] { Dataset::open(root); };

  SUBCASE("missing manifest") {
    std::filesystem::remove(root / kManifestFileName);
    requireInputError(open, manifestName, "does not exist");
  }
  SUBCASE("malformed JSON") {
    std::ofstream(root / kManifestFileName) << "{\"version\": 1, \"samples\": [";
    requireInputError(open, manifestName, "malformed JSON");
  }
  SUBCASE("unknown version") {
    editManifest(root, [](nlohmann::json& m) { m["version"] = 99; });
    requireInputError(open, manifestName, "unknown format version 99");
  }
  SUBCASE("missing field") {
    editManifest(root, [](nlohmann::json& m) { m.erase("width"); });
    requireInputError(open, manifestName, "missing field 'width'");
  }
  SUBCASE("missing view file") {
    std::filesystem::remove(root / "samples/s2.exr");
    requireInputError(open, manifestName + ": sample 2", "file 'samples/s2.exr' does not exist");
  }
  SUBCASE("absolute view file") {
    editManifest(root, [](nlohmann::json& m) { m["samples"][2]["file"] = "/etc/passwd"; });
    requireInputError(open, manifestName + ": sample 2", "file '/etc/passwd' is absolute");
  }
  SUBCASE("view file that climbs out of the data set") {
    editManifest(root, [](nlohmann::json& m) { m["probes"][0]["file"] = "samples/../../../../etc/hostname"; });
    requireInputError(open, manifestName + ": probe 0", "leaves the data set folder");
  }
  SUBCASE("view file that is a symlink out of the data set") {
    TemporaryDirectory elsewhere;
    writePanoramaExr(elsewhere.path() / "outside.exr", syntheticPanorama(32, 16, 9));
    std::filesystem::remove(root / "samples/s1.exr");
    std::filesystem::create_symlink(elsewhere.path() / "outside.exr", root / "samples/s1.exr");
    requireInputError(open, manifestName + ": sample 1", "leads outside the data set folder");
  }
  SUBCASE("view file that is a folder") {
    editManifest(root, [](nlohmann::json& m) { m["samples"][1]["file"] = "samples"; });
    requireInputError(open, manifestName + ": sample 1", "file 'samples' is not a regular file");
  }
  SUBCASE("fewer than 3 samples") {
    editManifest(root, [](nlohmann::json& m) { m["samples"] = {m["samples"][0], m["samples"][1]}; });
    requireInputError(open, manifestName, "2 samples; at least 3");
  }
  SUBCASE("duplicate sample positions") {
    editManifest(root, [](nlohmann::json& m) { m["samples"][3]["position"] = m["samples"][1]["position"]; });
    requireInputError(open, manifestName, "samples 1 and 3 share the position");
  }
  SUBCASE("position that is not three numbers") {
    editManifest(root, [](nlohmann::json& m) { m["samples"][0]["position"] = {1.0, "two", 3.0}; });
    requireInputError(open, manifestName, "samples[0].position");
  }
  SUBCASE("EXR of the wrong size") {
    writePanoramaExr(root / "samples/s1.exr", syntheticPanorama(16, 8, 1));
    const Dataset dataset = Dataset::open(root);
    requireInputError([&] { dataset.loadView(dataset.sample(1)); }, "samples/s1.exr", "size 16x8 but the manifest says 32x16");
  }
  SUBCASE("EXR missing the distance channel") {
    writeExrWithChannels(root / "samples/s1.exr", 32, 16, {"R", "G", "B"}, 1.0f);
    const Dataset dataset = Dataset::open(root);
    requireInputError([&] { dataset.loadView(dataset.sample(1)); }, "samples/s1.exr", "missing channel Z");
  }
  SUBCASE("EXR missing a color channel") {
    writeExrWithChannels(root / "samples/s1.exr", 32, 16, {"R", "B", "Z"}, 1.0f);
    const Dataset dataset = Dataset::open(root);
    requireInputError([&] { dataset.loadView(dataset.sample(1)); }, "samples/s1.exr", "missing channel G");
  }
  SUBCASE("NaN distance") {
    writeExrWithChannels(root / "samples/s1.exr", 32, 16, {"R", "G", "B", "Z"}, std::nanf(""));
    const Dataset dataset = Dataset::open(root);
    requireInputError([&] { dataset.loadView(dataset.sample(1)); }, "samples/s1.exr", "NaN distance");
  }
  SUBCASE("negative distance") {
    writeExrWithChannels(root / "samples/s1.exr", 32, 16, {"R", "G", "B", "Z"}, -2.0f);
    const Dataset dataset = Dataset::open(root);
    requireInputError([&] { dataset.loadView(dataset.sample(1)); }, "samples/s1.exr", "negative distance");
  }
  SUBCASE("EXR whose header claims a size larger than triwalk reads") {
    // Only the header is written: the reader must refuse it before
    // allocating 40000 x 20000 pixels.
    Imf::Header header(40000, 20000);
    for (const char* name : {"R", "G", "B", "Z"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    { Imf::OutputFile file((root / "samples/s1.exr").string().c_str(), header); }
    const Dataset dataset = Dataset::open(root);
    requireInputError([&] { dataset.loadView(dataset.sample(1)); }, "samples/s1.exr",
                      "size 40000x20000 is larger than triwalk reads (32768x16384)");
  }
  SUBCASE("corrupt EXR") {
    std::ofstream(root / "samples/s1.exr", std::ios::binary) << "this is not an OpenEXR file";
    const Dataset dataset = Dataset::open(root);
    requireInputError([&] { dataset.loadView(dataset.sample(1)); }, "samples/s1.exr", "cannot read OpenEXR");
  }
}

}  // namespace triwalk
