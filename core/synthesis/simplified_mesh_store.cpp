#include "core/synthesis/simplified_mesh_store.h"

#include "core/geometry/projection.h"
#include "core/support/errors.h"
#include "core/support/stable_hash.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <functional>
#include <span>

namespace triwalk {

namespace {

// A file: the header (sizes: the surface and sky index counts), then the
// surface and sky indices, then the orphans to the end of the file (none
// for a walking mesh). Format 01 had no orphans: its files are made again.
constexpr std::array<char, 8> kMeshMagic = {'T', 'W', 'M', 'E', 'S', 'H', '0', '2'};

// Everything the simplified triangles depend on.
uint64_t sourceKey(const ViewRecord& view, const Panorama& panorama, const WarpOptions& options) {
  StableHash hash;
  hash.addValue(kMeshMagic);
  hash.addValue(panorama.width());
  hash.addValue(panorama.height());
  hash.addBytes(std::as_bytes(std::span<const float>(panorama.distance.pixels)));
  hash.addValue(view.position);
  hash.addValue(view.yawDegrees);
  hash.addValue(options.stretchTest);
  hash.addValue(options.grazingAngleDegrees);
  hash.addValue(options.maxDepthRatio);
  hash.addValue(options.meshTolerancePixels);
  return hash.value();
}

uint64_t indicesChecksum(const SimplifiedTriangles& triangles) {
  StableHash hash;
  hash.addBytes(std::as_bytes(std::span<const uint32_t>(triangles.surface)));
  hash.addBytes(std::as_bytes(std::span<const uint32_t>(triangles.sky)));
  hash.addBytes(std::as_bytes(std::span<const uint32_t>(triangles.orphans)));
  return hash.value();
}

}  // namespace

SimplifiedMeshStore::SimplifiedMeshStore(const std::filesystem::path& datasetDirectory)
    : files_(datasetDirectory / "meshes", "simplified meshes") {}

SimplifiedMeshStore::SimplifiedMeshStore(const Dataset& dataset) : SimplifiedMeshStore(dataset.directory()) {}

std::filesystem::path SimplifiedMeshStore::file(const ViewRecord& view, int width, float tolerancePixels,
                                                float walkingScale) const {
  // view.file is a path inside the data set (checked when it was opened).
  // The default tolerance keeps the name stores were first written under.
  std::string tolerance;
  if (tolerancePixels != WarpOptions{}.meshTolerancePixels) {
    char text[32];
    std::snprintf(text, sizeof text, ".%.2fpx", double(tolerancePixels));
    tolerance = text;
  }
  if (walkingScale > 0.0f) {
    char text[32];
    std::snprintf(text, sizeof text, ".walking%.2f", double(walkingScale));
    tolerance += text;
  }
  return files_.folder() / (view.file + "." + std::to_string(width) + tolerance + ".mesh");
}

std::vector<uint32_t> SimplifiedMeshStore::walkingTriangles(const ViewRecord& view, const Panorama& panorama,
                                                            const WarpSource& source, const WarpOptions& options,
                                                            float scale) {
  TRIWALK_CHECK(options.mesh == SourceMesh::Simplified && scale > 0.0f && scale <= 1.0f,
                "a walking mesh is a simplified mesh's, for a scale in (0, 1]");
  const std::filesystem::path path = file(view, panorama.width(), options.meshTolerancePixels, scale);
  StableHash hash;
  hash.addValue(sourceKey(view, panorama, options));
  hash.addValue(scale);
  const uint64_t key = hash.value();
  const uint32_t vertexCount = uint32_t(panorama.width()) * uint32_t(panorama.height()) + 2;
  if (const std::optional<SimplifiedTriangles> stored = load(path, key, vertexCount)) {
    // A file whose vertices are not the source's is simplified again, as a malformed one.
    if (std::optional<std::vector<uint32_t>> triangles = source.sourceTriangles(*stored)) return std::move(*triangles);
  }
  const float tolerance = options.meshTolerancePixels;
  const SimplifiedTriangles coarser = source.coarserTriangles(panorama, tolerance / scale - tolerance);
  store(path, key, coarser);
  return source.sourceTriangles(coarser).value();
}

WarpSource SimplifiedMeshStore::source(const ViewRecord& view, const Panorama& panorama, const WarpOptions& options) {
  const float yaw = degreesToRadians(view.yawDegrees);
  if (options.mesh != SourceMesh::Simplified) {
    return WarpSource(panorama, view.position, yaw, options);
  }
  const std::filesystem::path path = file(view, panorama.width(), options.meshTolerancePixels);
  const uint64_t key = sourceKey(view, panorama, options);
  const uint32_t vertexCount = uint32_t(panorama.width()) * uint32_t(panorama.height()) + 2;  // pixels and poles
  if (std::optional<SimplifiedTriangles> stored = load(path, key, vertexCount)) {
    ++loaded_;
    return WarpSource(panorama, view.position, yaw, options, std::move(stored));
  }
  WarpSource source(panorama, view.position, yaw, options);
  ++simplified_;
  store(path, key, source.simplifiedTriangles());
  return source;
}

std::optional<SimplifiedTriangles> SimplifiedMeshStore::load(const std::filesystem::path& path, uint64_t key,
                                                              uint32_t vertexCount) const {
  const std::optional<DerivedFile> file = files_.read(path, kMeshMagic, key);
  if (!file) return std::nullopt;
  const auto [surfaceIndices, skyIndices] = file->header.sizes;
  const std::span<const std::byte> contents = file->contents();
  const size_t triangleBytes = (size_t(surfaceIndices) + size_t(skyIndices)) * sizeof(uint32_t);
  if (surfaceIndices % 3 != 0 || skyIndices % 3 != 0 || contents.size() < triangleBytes ||
      (contents.size() - triangleBytes) % sizeof(uint32_t) != 0) {
    return std::nullopt;
  }
  const auto indicesAt = [&](size_t first, size_t count) {
    std::vector<uint32_t> list(count);
    // An empty list's data() may be null, which memcpy must not be given.
    if (count > 0) std::memcpy(list.data(), contents.data() + first * sizeof(uint32_t), count * sizeof(uint32_t));
    return list;
  };
  SimplifiedTriangles triangles;
  triangles.surface = indicesAt(0, surfaceIndices);
  triangles.sky = indicesAt(surfaceIndices, skyIndices);
  triangles.orphans =
      indicesAt(size_t(surfaceIndices) + size_t(skyIndices), (contents.size() - triangleBytes) / sizeof(uint32_t));
  if (indicesChecksum(triangles) != file->header.checksum) return std::nullopt;
  for (const std::vector<uint32_t>* list : {&triangles.surface, &triangles.sky, &triangles.orphans}) {
    for (const uint32_t v : *list) {
      if (v >= vertexCount) return std::nullopt;
    }
  }
  if (std::adjacent_find(triangles.orphans.begin(), triangles.orphans.end(), std::greater_equal<>()) !=
      triangles.orphans.end()) {
    return std::nullopt;
  }
  return triangles;
}

void SimplifiedMeshStore::store(const std::filesystem::path& path, uint64_t key, const SimplifiedTriangles& triangles) {
  const DerivedFileHeader header{kMeshMagic,
                                 key,
                                 indicesChecksum(triangles),
                                 {uint32_t(triangles.surface.size()), uint32_t(triangles.sky.size())}};
  files_.write(path, header,
               {std::as_bytes(std::span(triangles.surface)), std::as_bytes(std::span(triangles.sky)),
                std::as_bytes(std::span(triangles.orphans))});
}

}  // namespace triwalk
