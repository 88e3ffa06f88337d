// The data set's store of simplified source meshes: a view is simplified
// once and read back after, with the very same triangles; anything in the
// store that does not belong to this source (another tolerance, a changed
// panorama, a damaged file) is simplified again, and a store that cannot
// be written costs time only.

#include "core/geometry/projection.h"
#include "core/synthesis/simplified_mesh_store.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>

using namespace triwalk;

namespace {

constexpr int kStoreWidth = 256;

WarpOptions simplifiedOptions(float tolerancePixels = 0.25f) {
  WarpOptions options;
  options.mesh = SourceMesh::Simplified;
  options.meshTolerancePixels = tolerancePixels;
  return options;
}

void requireSameSource(const WarpSource& a, const WarpSource& b, glm::vec3 destination) {
  REQUIRE(a.simplifiedTriangles().surface == b.simplifiedTriangles().surface);
  REQUIRE(a.simplifiedTriangles().sky == b.simplifiedTriangles().sky);
  REQUIRE(a.simplifiedTriangles().orphans == b.simplifiedTriangles().orphans);
  REQUIRE(a.triangleCount() == b.triangleCount());
  const DestinationCamera camera = DestinationCamera::panorama(destination, kStoreWidth, kStoreWidth / 2);
  const WarpLayer layerA = warpToCamera(a, camera, WarpMethod::Mesh);
  const WarpLayer layerB = warpToCamera(b, camera, WarpMethod::Mesh);
  CHECK(layerA.color.pixels == layerB.color.pixels);
  CHECK(layerA.distance.pixels == layerB.distance.pixels);
  CHECK(layerA.covered == layerB.covered);
}

// Four analytic samples at kStoreWidth, written into directory.
Dataset meshDataset(const testing::TemporaryDirectory& directory) {
  testing::writeAnalyticDataset(directory.path(), 2, 2, kStoreWidth, 0);
  return Dataset::open(directory.path());
}

void overwriteByte(const std::filesystem::path& path, std::streamoff offset) {
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  file.seekg(offset);
  const char byte = char(file.get());
  file.seekp(offset);
  file.put(char(byte ^ 0x5a));
}

}  // namespace

TEST_CASE("a view's simplified mesh is computed once, kept in the data set, and read back identical") {
  testing::TemporaryDirectory directory;
  const Dataset dataset = meshDataset(directory);
  const ViewRecord& view = dataset.sample(1);
  const Panorama panorama = dataset.loadView(view);
  const glm::vec3 destination = dataset.sample(2).position;
  const WarpSource fresh(panorama, view.position, degreesToRadians(view.yawDegrees), simplifiedOptions());
  REQUIRE(fresh.triangleCount() > 0);

  SimplifiedMeshStore store(dataset);
  const std::filesystem::path file = store.file(view, kStoreWidth, simplifiedOptions().meshTolerancePixels);
  CHECK(file.parent_path().string().starts_with((directory.path() / "meshes").string()));
  requireSameSource(store.source(view, panorama, simplifiedOptions()), fresh, destination);
  CHECK(store.simplified() == 1);
  CHECK(store.loaded() == 0);
  REQUIRE(std::filesystem::is_regular_file(file));
  const auto written = std::filesystem::last_write_time(file);

  // A second store (a later run) reads it instead of simplifying.
  SimplifiedMeshStore later(dataset);
  requireSameSource(later.source(view, panorama, simplifiedOptions()), fresh, destination);
  CHECK(later.loaded() == 1);
  CHECK(later.simplified() == 0);
  CHECK(std::filesystem::last_write_time(file) == written);

  SUBCASE("another tolerance is kept in a file of its own, beside the first") {
    const WarpSource coarse(panorama, view.position, degreesToRadians(view.yawDegrees), simplifiedOptions(2.0f));
    REQUIRE(coarse.triangleCount() < fresh.triangleCount());
    requireSameSource(later.source(view, panorama, simplifiedOptions(2.0f)), coarse, destination);
    CHECK(later.simplified() == 1);
    const std::filesystem::path coarseFile = later.file(view, kStoreWidth, 2.0f);
    CHECK(coarseFile != file);
    CHECK(std::filesystem::is_regular_file(coarseFile));
    // Both read back: runs that alternate the two tolerances never simplify again.
    requireSameSource(later.source(view, panorama, simplifiedOptions(2.0f)), coarse, destination);
    requireSameSource(later.source(view, panorama, simplifiedOptions()), fresh, destination);
    CHECK(later.loaded() == 3);
    CHECK(later.simplified() == 1);
    CHECK(std::filesystem::last_write_time(file) == written);
  }
  SUBCASE("a changed panorama is simplified again") {
    Panorama moved = panorama;
    for (float& d : moved.distance.pixels) d *= 1.01f;
    later.source(view, moved, simplifiedOptions());
    CHECK(later.simplified() == 1);
    CHECK(later.loaded() == 1);  // only the read above
  }
  SUBCASE("a damaged or truncated file is simplified again and mended") {
    const std::uintmax_t size = std::filesystem::file_size(file);
    overwriteByte(file, std::streamoff(size) - 5);  // an index
    requireSameSource(later.source(view, panorama, simplifiedOptions()), fresh, destination);
    CHECK(later.simplified() == 1);
    std::filesystem::resize_file(file, size - 4);
    requireSameSource(later.source(view, panorama, simplifiedOptions()), fresh, destination);
    CHECK(later.simplified() == 2);
    overwriteByte(file, 0);  // the magic
    requireSameSource(later.source(view, panorama, simplifiedOptions()), fresh, destination);
    CHECK(later.simplified() == 3);
    requireSameSource(later.source(view, panorama, simplifiedOptions()), fresh, destination);
    CHECK(later.loaded() == 2);
  }
}

TEST_CASE("a source made from its stored mesh has the simplified source's vertices and orphans, bit for bit") {
  testing::TemporaryDirectory directory;
  const Dataset dataset = meshDataset(directory);
  const ViewRecord& view = dataset.sample(2);
  Panorama spiked = dataset.loadView(view);
  // A pixel far nearer than its neighbours: the stretch test drops all six
  // of its triangles, so it is splatted alone, an orphan. A source read
  // from the store runs no stretch test and must know it all the same.
  const uint32_t spike = 40 * kStoreWidth + 100;
  spiked.distance.pixels[spike] *= 0.3f;
  const WarpSource fresh(spiked, view.position, degreesToRadians(view.yawDegrees), simplifiedOptions());
  const std::vector<uint32_t>& orphans = fresh.simplifiedTriangles().orphans;
  REQUIRE(std::binary_search(orphans.begin(), orphans.end(), spike));

  SimplifiedMeshStore(dataset).source(view, spiked, simplifiedOptions());
  SimplifiedMeshStore later(dataset);
  const WarpSource read = later.source(view, spiked, simplifiedOptions());
  REQUIRE(later.loaded() == 1);
  REQUIRE(read.vertexCount() == fresh.vertexCount());
  REQUIRE(read.pixelVertexCount() == fresh.pixelVertexCount());
  int orphanVertices = 0;
  for (uint32_t v = 0; v < fresh.vertexCount(); ++v) {
    CHECK(read.point(v) == fresh.point(v));
    CHECK(read.color(v) == fresh.color(v));
    CHECK(read.atInfinity(v) == fresh.atInfinity(v));
    CHECK(read.orphan(v) == fresh.orphan(v));
    orphanVertices += fresh.orphan(v);
  }
  CHECK(size_t(orphanVertices) == orphans.size());
  requireSameSource(read, fresh, dataset.sample(0).position);
}

TEST_CASE("the grid needs no store, and a store that cannot be written only costs the time") {
  testing::TemporaryDirectory directory;
  const Dataset dataset = meshDataset(directory);
  const ViewRecord& view = dataset.sample(0);
  const Panorama panorama = dataset.loadView(view);

  SimplifiedMeshStore store(dataset);
  CHECK(store.source(view, panorama, WarpOptions{}).mesh() == SourceMesh::Grid);
  CHECK_FALSE(std::filesystem::exists(directory.path() / "meshes"));

  // A file where the store's directory should be: nothing can be kept.
  std::ofstream(directory.path() / "meshes") << "not a directory";
  const WarpSource fresh(panorama, view.position, degreesToRadians(view.yawDegrees), simplifiedOptions());
  requireSameSource(store.source(view, panorama, simplifiedOptions()), fresh, dataset.sample(3).position);
  requireSameSource(store.source(view, panorama, simplifiedOptions()), fresh, dataset.sample(3).position);
  CHECK(store.simplified() == 2);
  CHECK(store.loaded() == 0);
}
