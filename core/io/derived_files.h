#pragma once
// What the data set's stores share (the simplified meshes of
// core/io/simplified_mesh_store.h, the downsampled panoramas of
// core/io/downsampled_panorama_store.h): files triwalk derives from a data
// set's views and keeps in a folder of it, to be read back instead of
// computed again. A file is read whole or not at all and written
// atomically. They are caches: a store that cannot be written (read-only,
// full) only costs the time, and says so once on stderr.

#include <atomic>
#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <mutex>
#include <optional>
#include <span>
#include <string>

namespace triwalk {

class DerivedFiles {
public:
  // folder: where the files go; kind: what they are, for the warning
  // ("simplified meshes").
  DerivedFiles(std::filesystem::path folder, std::string kind);

  const std::filesystem::path& folder() const { return folder_; }

  // A file's bytes, or nothing when it is missing or cannot be read.
  std::optional<std::string> read(const std::filesystem::path& path) const;

  // Writes the parts one after another into path (creating its folders),
  // atomically. A failure only warns, the first time. Thread-safe.
  void write(const std::filesystem::path& path, std::initializer_list<std::span<const std::byte>> parts);

private:
  std::filesystem::path folder_;
  std::string kind_;
  std::atomic<bool> warned_ = false;
  std::mutex directories_;
};

}  // namespace triwalk
