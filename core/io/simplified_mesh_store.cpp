#include "core/io/simplified_mesh_store.h"

#include "core/geometry/projection.h"
#include "core/io/atomic_file.h"
#include "core/support/errors.h"

#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <span>

namespace triwalk {

namespace {

// A file: magic, the source's key, the checksum of the indices, the two
// index counts, then the surface and sky indices (host byte order; a file
// from a machine of the other order fails its key and is made again).
constexpr std::array<char, 8> kMagic = {'T', 'W', 'M', 'E', 'S', 'H', '0', '1'};
struct Header {
  std::array<char, 8> magic;
  uint64_t key;
  uint64_t checksum;
  uint32_t surfaceIndices, skyIndices;
};

// FNV-1a: a stable 64-bit hash, the same on every run and machine.
class Fnv1a {
public:
  void add(std::span<const std::byte> bytes) {
    for (const std::byte b : bytes) hash_ = (hash_ ^ uint64_t(b)) * 0x100000001b3ull;
  }
  template <typename T>
  void add(const T& value) {
    add(std::as_bytes(std::span<const T>(&value, 1)));
  }
  uint64_t value() const { return hash_; }

private:
  uint64_t hash_ = 0xcbf29ce484222325ull;
};

// Everything the simplified triangles depend on.
uint64_t sourceKey(const ViewRecord& view, const Panorama& panorama, const WarpOptions& options) {
  Fnv1a hash;
  hash.add(kMagic);
  hash.add(panorama.width());
  hash.add(panorama.height());
  hash.add(std::as_bytes(std::span<const float>(panorama.distance.pixels)));
  hash.add(view.position);
  hash.add(view.yawDegrees);
  hash.add(options.stretchTest);
  hash.add(options.grazingAngleDegrees);
  hash.add(options.maxDepthRatio);
  hash.add(options.meshTolerancePixels);
  return hash.value();
}

uint64_t indicesChecksum(const SimplifiedTriangles& triangles) {
  Fnv1a hash;
  hash.add(std::as_bytes(std::span<const uint32_t>(triangles.surface)));
  hash.add(std::as_bytes(std::span<const uint32_t>(triangles.sky)));
  return hash.value();
}

}  // namespace

SimplifiedMeshStore::SimplifiedMeshStore(const Dataset& dataset) : directory_(dataset.directory() / "meshes") {}

std::filesystem::path SimplifiedMeshStore::file(const ViewRecord& view, int width, float tolerancePixels) const {
  // view.file is a path inside the data set (checked when it was opened).
  // The default tolerance keeps the name stores were first written under.
  std::string tolerance;
  if (tolerancePixels != WarpOptions{}.meshTolerancePixels) {
    char text[32];
    std::snprintf(text, sizeof text, ".%.2fpx", double(tolerancePixels));
    tolerance = text;
  }
  return directory_ / (view.file + "." + std::to_string(width) + tolerance + ".mesh");
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
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return std::nullopt;
  std::string bytes;
  try {
    bytes = readTextFile(path);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  Header header{};
  if (bytes.size() < sizeof(Header)) return std::nullopt;
  std::memcpy(&header, bytes.data(), sizeof(Header));
  const size_t indexCount = size_t(header.surfaceIndices) + size_t(header.skyIndices);
  if (header.magic != kMagic || header.key != key || header.surfaceIndices % 3 != 0 || header.skyIndices % 3 != 0 ||
      bytes.size() != sizeof(Header) + indexCount * sizeof(uint32_t)) {
    return std::nullopt;
  }
  const auto indicesAt = [&](size_t first, size_t count) {
    std::vector<uint32_t> list(count);
    // An empty list's data() may be null, which memcpy must not be given.
    const char* from = bytes.data() + sizeof(Header) + first * sizeof(uint32_t);
    if (count > 0) std::memcpy(list.data(), from, count * sizeof(uint32_t));
    return list;
  };
  SimplifiedTriangles triangles;
  triangles.surface = indicesAt(0, header.surfaceIndices);
  triangles.sky = indicesAt(header.surfaceIndices, header.skyIndices);
  if (indicesChecksum(triangles) != header.checksum) return std::nullopt;
  for (const std::vector<uint32_t>* list : {&triangles.surface, &triangles.sky}) {
    for (const uint32_t v : *list) {
      if (v >= vertexCount) return std::nullopt;
    }
  }
  return triangles;
}

void SimplifiedMeshStore::store(const std::filesystem::path& path, uint64_t key, const SimplifiedTriangles& triangles) {
  try {
    {
      std::lock_guard lock(directories_);
      std::filesystem::create_directories(path.parent_path());
    }
    Header header{kMagic, key, indicesChecksum(triangles), uint32_t(triangles.surface.size()),
                  uint32_t(triangles.sky.size())};
    writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
      std::ofstream stream(temporary, std::ios::binary);
      stream.write(reinterpret_cast<const char*>(&header), sizeof(header));
      for (const std::vector<uint32_t>* list : {&triangles.surface, &triangles.sky}) {
        if (list->empty()) continue;  // data() may be null
        stream.write(reinterpret_cast<const char*>(list->data()), std::streamsize(list->size() * sizeof(uint32_t)));
      }
      stream.close();
      if (!stream) throw InputError(path.string(), "cannot write file");
    });
  } catch (const std::exception& failure) {
    if (!warned_.exchange(true)) {
      std::cerr << "triwalk: simplified meshes are not kept (" << failure.what()
                << "); they will be simplified again next time\n";
    }
  }
}

}  // namespace triwalk
