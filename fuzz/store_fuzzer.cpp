// Fuzzes the readers of the data set's stores (core/io/derived_files.h):
// any bytes as a view's downsampled copy and as its simplified mesh, in a
// copy of fuzz/seeds/dataset. A store is a cache, so no file may make it
// fail or change a result: whatever the bytes, both must come back
// exactly as made from the view's EXR file, or the harness aborts.

#include "core/io/dataset.h"
#include "core/io/downsampled_panorama_store.h"
#include "core/synthesis/simplified_mesh_store.h"
#include "core/synthesis/warp.h"
#include "fuzz/fuzz_input.h"

#include <cstdlib>
#include <cstring>
#include <fstream>

namespace {

using namespace triwalk;

constexpr int kWidth = 16;  // half the seed data set's width

struct Truth {
  Dataset dataset;
  Panorama copy;
  SimplifiedTriangles triangles;
};

WarpOptions simplifiedOptions() {
  WarpOptions options;
  options.mesh = SourceMesh::Simplified;
  return options;
}

const Truth& truth() {
  static const Truth made = [] {
    const std::filesystem::path directory = fuzz::scratchDirectory() / "dataset";
    std::filesystem::remove_all(directory);
    std::filesystem::copy(TRIWALK_FUZZ_DATASET, directory, std::filesystem::copy_options::recursive);
    Dataset dataset = Dataset::open(directory);
    const ViewRecord& view = dataset.sample(0);
    Panorama copy = dataset.loadView(view, kWidth);
    SimplifiedTriangles triangles =
        WarpSource(copy, view.position, degreesToRadians(view.yawDegrees), simplifiedOptions()).simplifiedTriangles();
    return Truth{std::move(dataset), std::move(copy), std::move(triangles)};
  }();
  return made;
}

void writeBytes(const std::filesystem::path& path, const uint8_t* data, size_t size) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
}

bool sameBits(const Panorama& a, const Panorama& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.color.pixels.data(), b.color.pixels.data(), a.color.pixels.size() * sizeof(glm::vec3)) == 0 &&
         std::memcmp(a.distance.pixels.data(), b.distance.pixels.data(), a.distance.pixels.size() * sizeof(float)) == 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const Truth& expected = truth();
  const ViewRecord& view = expected.dataset.sample(0);

  DownsampledPanoramaStore panoramas(expected.dataset);
  writeBytes(panoramas.file(view, kWidth), data, size);
  const Panorama copy = panoramas.load(view, kWidth);
  if (!sameBits(copy, expected.copy)) std::abort();

  SimplifiedMeshStore meshes(expected.dataset);
  writeBytes(meshes.file(view, kWidth, simplifiedOptions().meshTolerancePixels), data, size);
  const WarpSource source = meshes.source(view, copy, simplifiedOptions());
  if (source.simplifiedTriangles().surface != expected.triangles.surface ||
      source.simplifiedTriangles().sky != expected.triangles.sky ||
      source.simplifiedTriangles().orphans != expected.triangles.orphans) {
    std::abort();
  }
  return 0;
}
