// The data set's store of downsampled panoramas: a view's copy at the error
// width is made once and read back after, bit for bit what downsampling its
// file gives; a copy that does not belong to the file as it is now (the
// file rewritten, the copy damaged or holding values no panorama may have)
// is made again; capture's copies, kept from the panorama in memory, equal
// the ones made from the file; and a decimation finds everything capture
// kept.

#include "core/io/downsampled_panorama_store.h"
#include "core/io/exr_io.h"
#include "core/selection/selection_inputs.h"
#include "core/selection/triangle_error.h"
#include "core/support/stable_hash.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

using namespace triwalk;

namespace {

constexpr int kFullWidth = 512;
constexpr int kCopyWidth = 128;  // a quarter

Dataset panoramaDataset(const testing::TemporaryDirectory& directory, int probes = 0) {
  testing::writeAnalyticDataset(directory.path(), 2, 2, kFullWidth, probes);
  return Dataset::open(directory.path());
}

void requireSamePanorama(const Panorama& a, const Panorama& b) {
  REQUIRE(a.width() == b.width());
  REQUIRE(a.height() == b.height());
  // Bit for bit: memcmp, since == would call -0 and 0 equal.
  CHECK(std::memcmp(a.color.pixels.data(), b.color.pixels.data(), a.color.pixels.size() * sizeof(glm::vec3)) == 0);
  CHECK(std::memcmp(a.distance.pixels.data(), b.distance.pixels.data(), a.distance.pixels.size() * sizeof(float)) == 0);
}

std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace

TEST_CASE("a view's downsampled copy is made once, kept in the data set, and read back bit for bit") {
  testing::TemporaryDirectory directory;
  const Dataset dataset = panoramaDataset(directory);
  const ViewRecord& view = dataset.sample(1);
  const Panorama fromFile = dataset.loadView(view, kCopyWidth);

  DownsampledPanoramaStore store(dataset);
  const std::filesystem::path file = store.file(view, kCopyWidth);
  CHECK(file == directory.path() / "downsampled/samples/s1.exr.128.pano");
  requireSamePanorama(store.load(view, kCopyWidth), fromFile);
  CHECK(store.downsampled() == 1);
  CHECK(store.loaded() == 0);
  REQUIRE(std::filesystem::is_regular_file(file));
  const auto written = std::filesystem::last_write_time(file);

  // A second store (a later run) reads it instead of decoding the EXR.
  DownsampledPanoramaStore later(dataset);
  requireSamePanorama(later.load(view, kCopyWidth), fromFile);
  CHECK(later.loaded() == 1);
  CHECK(later.downsampled() == 0);
  CHECK(std::filesystem::last_write_time(file) == written);

  SUBCASE("each width has its copy, and the full width is read from the file, never kept") {
    requireSamePanorama(later.load(view, kFullWidth / 2), dataset.loadView(view, kFullWidth / 2));
    CHECK(std::filesystem::is_regular_file(later.file(view, kFullWidth / 2)));
    requireSamePanorama(later.load(view, kFullWidth), dataset.loadView(view));
    CHECK_FALSE(std::filesystem::exists(later.file(view, kFullWidth)));
    CHECK(later.downsampled() == 1);
  }
  SUBCASE("a rewritten view file is downsampled again: the copy follows the file") {
    const Panorama other = dataset.loadView(dataset.sample(2));
    writePanoramaExr(directory.path() / view.file, other);
    requireSamePanorama(later.load(view, kCopyWidth), dataset.loadView(dataset.sample(2), kCopyWidth));
    CHECK(later.downsampled() == 1);
    requireSamePanorama(later.load(view, kCopyWidth), dataset.loadView(dataset.sample(2), kCopyWidth));
    CHECK(later.loaded() == 2);
  }
  SUBCASE("a damaged, truncated or foreign copy is made again and mended") {
    const std::string good = fileBytes(file);
    std::string damaged = good;
    damaged[damaged.size() - 3] ^= 0x5a;  // a distance
    writeBytes(file, damaged);
    requireSamePanorama(later.load(view, kCopyWidth), fromFile);
    CHECK(later.downsampled() == 1);
    CHECK(fileBytes(file) == good);
    writeBytes(file, good.substr(0, good.size() - 4));
    requireSamePanorama(later.load(view, kCopyWidth), fromFile);
    CHECK(later.downsampled() == 2);
    // Another view's copy under this view's name: its key is another file's.
    DownsampledPanoramaStore(dataset).load(dataset.sample(3), kCopyWidth);
    std::filesystem::copy_file(later.file(dataset.sample(3), kCopyWidth), file,
                               std::filesystem::copy_options::overwrite_existing);
    requireSamePanorama(later.load(view, kCopyWidth), fromFile);
    CHECK(later.downsampled() == 3);
    CHECK(fileBytes(file) == good);
  }
  SUBCASE("a copy whose checksum fits but which holds a NaN is made again") {
    // Written as the store writes, checksum and all: only the values betray it.
    std::string bytes = fileBytes(file);
    const size_t header = 8 + 8 + 8 + 4 + 4, pixels = size_t(kCopyWidth) * size_t(kCopyWidth / 2);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(bytes.data() + header + pixels * sizeof(glm::vec3), &nan, sizeof nan);  // the first distance
    StableHash checksum;
    checksum.addBytes(std::as_bytes(std::span(bytes.data() + header, pixels * sizeof(glm::vec3))));
    checksum.addBytes(std::as_bytes(std::span(bytes.data() + header + pixels * sizeof(glm::vec3), pixels * sizeof(float))));
    const uint64_t value = checksum.value();
    std::memcpy(bytes.data() + 16, &value, sizeof value);
    writeBytes(file, bytes);
    const Panorama loaded = later.load(view, kCopyWidth);
    CHECK_FALSE(std::isnan(loaded.distance.pixels[0]));
    requireSamePanorama(loaded, fromFile);
    CHECK(later.downsampled() == 1);
  }
}

TEST_CASE("a missing view file is the file reader's one-line error, and a store that cannot be written only costs the time") {
  testing::TemporaryDirectory directory;
  const Dataset dataset = panoramaDataset(directory);
  DownsampledPanoramaStore store(dataset);
  std::filesystem::remove(directory.path() / dataset.sample(0).file);
  testing::requireInputError([&] { store.load(dataset.sample(0), kCopyWidth); },
                             (directory.path() / dataset.sample(0).file).string(), "file does not exist");

  // A file where the store's directory should be: nothing can be kept.
  std::ofstream(directory.path() / "downsampled") << "not a directory";
  const ViewRecord& view = dataset.sample(1);
  requireSamePanorama(store.load(view, kCopyWidth), dataset.loadView(view, kCopyWidth));
  requireSamePanorama(store.load(view, kCopyWidth), dataset.loadView(view, kCopyWidth));
  CHECK(store.downsampled() == 2);
  CHECK(store.loaded() == 0);
}

TEST_CASE("a copy kept from the panorama just written equals the one made from its file, colours rounded to halves") {
  testing::TemporaryDirectory directory;
  const Dataset dataset = panoramaDataset(directory);
  const ViewRecord& view = dataset.sample(0);
  // Colours a half float cannot hold, as a renderer gives them.
  Panorama rendered = dataset.loadView(view);
  for (glm::vec3& color : rendered.color.pixels) color = color * 0.9137f + glm::vec3(0.0123f);
  writePanoramaExr(directory.path() / view.file, rendered);

  DownsampledPanoramaStore capture(dataset);
  const Panorama kept = capture.keep(view, rendered, kCopyWidth);
  DownsampledPanoramaStore later(dataset);
  requireSamePanorama(later.load(view, kCopyWidth), kept);
  CHECK(later.loaded() == 1);
  std::filesystem::remove(later.file(view, kCopyWidth));
  requireSamePanorama(later.load(view, kCopyWidth), kept);
  CHECK(later.downsampled() == 1);
}

TEST_CASE("what capture keeps of each view is what a decimation at the defaults reads, identical to loading afresh") {
  testing::TemporaryDirectory directory;
  const Dataset dataset = panoramaDataset(directory, 2);
  const glm::ivec2 fullSize(kFullWidth, kFullWidth / 2);
  SelectionInputKeeper keeper(directory.path(), fullSize);
  CHECK(keeper.errorWidth() == errorWidthFor(dataset, 0));
  for (int i = 0; i < dataset.sampleCount(); ++i) keeper.keep(dataset.sample(i), true, dataset.loadView(dataset.sample(i)));
  for (int i = 0; i < dataset.probeCount(); ++i) keeper.keep(dataset.probe(i), false, dataset.loadView(dataset.probe(i)));

  TriangleErrorSettings settings;
  settings.width = errorWidthFor(dataset, 0);
  settings.synthesis = withSelectionDefaults(settings.synthesis);
  DatasetTriangleErrors kept(dataset, settings, LoadedViews::SamplesAndProbes, true);
  CHECK(kept.loads().panoramasRead == dataset.sampleCount() + dataset.probeCount());
  CHECK(kept.loads().panoramasDownsampled == 0);
  CHECK(kept.loads().meshesRead == dataset.sampleCount());
  CHECK(kept.loads().meshesSimplified == 0);

  std::filesystem::remove_all(directory.path() / "downsampled");
  std::filesystem::remove_all(directory.path() / "meshes");
  DatasetTriangleErrors fresh(dataset, settings, LoadedViews::SamplesAndProbes, true);
  CHECK(fresh.loads().panoramasDownsampled == dataset.sampleCount() + dataset.probeCount());
  CHECK(fresh.loads().meshesSimplified == dataset.sampleCount());
  for (int i = 0; i < dataset.sampleCount(); ++i) {
    CHECK(kept.sampleDisplay(i).pixels == fresh.sampleDisplay(i).pixels);
    CHECK(kept.source(i).simplifiedTriangles().surface == fresh.source(i).simplifiedTriangles().surface);
  }
  for (int i = 0; i < dataset.probeCount(); ++i) CHECK(kept.probeDisplay(i).pixels == fresh.probeDisplay(i).pixels);
  const std::vector<Triangle> triangles = {{0, 1, 2}, {1, 2, 3}};
  std::vector<double> keptErrors(2), freshErrors(2);
  kept.computeErrors(triangles, keptErrors);
  fresh.computeErrors(triangles, freshErrors);
  CHECK(keptErrors == freshErrors);
}
