#pragma once
// What the data set's stores share (the simplified meshes of
// core/synthesis/simplified_mesh_store.h, the downsampled panoramas of
// core/io/downsampled_panorama_store.h): files triwalk derives from a data
// set's views and keeps in a folder of it, to be read back instead of
// computed again. A file is a header (DerivedFileHeader) and its contents,
// read whole or not at all and written atomically. They are caches: a store
// that cannot be written (read-only, full) only costs the time, and says so
// once on stderr.

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <mutex>
#include <optional>
#include <span>
#include <string>

namespace triwalk {

// How every store file begins (host byte order; a file from a machine of
// the other order fails its key or checksum and is made again).
struct DerivedFileHeader {
  std::array<char, 8> magic;  // the store's file format
  uint64_t key;               // of everything the contents depend on
  uint64_t checksum;          // of the contents, as the store computes it
  uint32_t sizes[2];          // the contents' two sizes, as the store defines them
};

// A store file as read: its header and the bytes after it.
struct DerivedFile {
  DerivedFileHeader header;
  std::string bytes;  // the whole file

  std::span<const std::byte> contents() const {
    return std::as_bytes(std::span(bytes)).subspan(sizeof(DerivedFileHeader));
  }
};

class DerivedFiles {
public:
  // folder: where the files go; kind: what they are, for the warning
  // ("simplified meshes").
  DerivedFiles(std::filesystem::path folder, std::string kind);

  const std::filesystem::path& folder() const { return folder_; }

  // The file at path if its header has this magic and key; nothing when it
  // is missing, cannot be read, is shorter than a header or is another's.
  // The store checks the sizes and the checksum.
  std::optional<DerivedFile> read(const std::filesystem::path& path, const std::array<char, 8>& magic,
                                  uint64_t key) const;

  // Writes the header and then the parts into path (creating its folders),
  // atomically. A failure only warns, the first time. Thread-safe.
  void write(const std::filesystem::path& path, const DerivedFileHeader& header,
             std::initializer_list<std::span<const std::byte>> parts);

private:
  std::filesystem::path folder_;
  std::string kind_;
  std::atomic<bool> warned_ = false;
  std::mutex directories_;
};

}  // namespace triwalk
