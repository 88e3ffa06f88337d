#include "core/io/downsampled_panorama_store.h"

#include "core/image/panorama_resample.h"
#include "core/io/exr_io.h"
#include "core/support/errors.h"
#include "core/support/stable_hash.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <span>
#include <vector>

namespace triwalk {

namespace {

// A file: the header (sizes: width and height), then the colour (three
// floats a pixel) and the distance (one), row by row.
constexpr std::array<char, 8> kPanoramaMagic = {'T', 'W', 'P', 'A', 'N', 'O', '0', '1'};
static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "colours are written as three packed floats");

uint64_t pixelsChecksum(const Panorama& panorama) {
  StableHash hash;
  hash.addBytes(std::as_bytes(std::span(panorama.color.pixels)));
  hash.addBytes(std::as_bytes(std::span(panorama.distance.pixels)));
  return hash.value();
}

bool holdsPanoramaValues(const Panorama& panorama) {
  return std::all_of(panorama.color.pixels.begin(), panorama.color.pixels.end(), acceptedPanoramaColor) &&
         std::all_of(panorama.distance.pixels.begin(), panorama.distance.pixels.end(), acceptedPanoramaDistance);
}

}  // namespace

DownsampledPanoramaStore::DownsampledPanoramaStore(const std::filesystem::path& datasetDirectory, glm::ivec2 fullSize)
    : datasetDirectory_(datasetDirectory), fullSize_(fullSize),
      files_(datasetDirectory / "downsampled", "downsampled panoramas") {}

DownsampledPanoramaStore::DownsampledPanoramaStore(const Dataset& dataset)
    : DownsampledPanoramaStore(dataset.directory(), glm::ivec2(dataset.manifest().width, dataset.manifest().height)) {}

std::filesystem::path DownsampledPanoramaStore::file(const ViewRecord& view, int width) const {
  // view.file is a path inside the data set (checked when it was opened).
  return files_.folder() / (view.file + "." + std::to_string(width) + ".pano");
}

int DownsampledPanoramaStore::factorOf(int width) const {
  TRIWALK_CHECK(width > 0 && fullSize_.x % width == 0 && fullSize_.y % (fullSize_.x / width) == 0,
                "a downsampled width must divide the data set's by a whole number");
  return fullSize_.x / width;
}

std::optional<uint64_t> DownsampledPanoramaStore::keyOf(const ViewRecord& view, int width) const {
  StableHash hash;
  hash.addValue(kPanoramaMagic);
  hash.addValue(fullSize_);
  hash.addValue(width);
  std::ifstream stream(datasetDirectory_ / view.file, std::ios::binary);
  if (!stream) return std::nullopt;
  std::vector<char> chunk(size_t(1) << 20);
  while (stream) {
    stream.read(chunk.data(), std::streamsize(chunk.size()));
    hash.addBytes(std::as_bytes(std::span(chunk.data(), size_t(stream.gcount()))));
  }
  if (stream.bad()) return std::nullopt;
  return hash.value();
}

Panorama DownsampledPanoramaStore::load(const ViewRecord& view, int width) {
  const int factor = factorOf(width);
  const std::filesystem::path source = datasetDirectory_ / view.file;
  if (factor == 1) return readPanoramaExr(source, fullSize_);
  const std::filesystem::path path = file(view, width);
  const std::optional<uint64_t> key = keyOf(view, width);
  if (key) {
    if (std::optional<Panorama> kept = read(path, *key, width)) {
      ++loaded_;
      return std::move(*kept);
    }
  }
  Panorama copy = downsamplePanorama(readPanoramaExr(source, fullSize_), factor);
  ++downsampled_;
  if (key) store(path, *key, copy);
  return copy;
}

Panorama DownsampledPanoramaStore::keep(const ViewRecord& view, const Panorama& full, int width) {
  const int factor = factorOf(width);
  if (factor == 1) return asWrittenToExr(full);
  Panorama copy = downsamplePanorama(asWrittenToExr(full), factor);
  ++downsampled_;
  if (const std::optional<uint64_t> key = keyOf(view, width)) store(file(view, width), *key, copy);
  return copy;
}

std::optional<Panorama> DownsampledPanoramaStore::read(const std::filesystem::path& path, uint64_t key, int width) const {
  const std::optional<DerivedFile> file = files_.read(path, kPanoramaMagic, key);
  const int height = fullSize_.y / factorOf(width);
  const size_t pixels = size_t(width) * size_t(height);
  if (!file || file->header.sizes[0] != uint32_t(width) || file->header.sizes[1] != uint32_t(height) ||
      file->contents().size() != pixels * 4 * sizeof(float)) {
    return std::nullopt;
  }
  Panorama copy{ColorImage(width, height), ScalarImage(width, height)};
  const std::byte* from = file->contents().data();
  std::memcpy(copy.color.pixels.data(), from, pixels * sizeof(glm::vec3));
  std::memcpy(copy.distance.pixels.data(), from + pixels * sizeof(glm::vec3), pixels * sizeof(float));
  if (pixelsChecksum(copy) != file->header.checksum || !holdsPanoramaValues(copy)) return std::nullopt;
  return copy;
}

void DownsampledPanoramaStore::store(const std::filesystem::path& path, uint64_t key, const Panorama& copy) {
  const DerivedFileHeader header{
      kPanoramaMagic, key, pixelsChecksum(copy), {uint32_t(copy.width()), uint32_t(copy.height())}};
  files_.write(path, header, {std::as_bytes(std::span(copy.color.pixels)), std::as_bytes(std::span(copy.distance.pixels))});
}

}  // namespace triwalk
