#pragma once
// Quake 3 levels come as .pk3 archives (zip) holding several maps and
// their textures. Assimp's importer reads the first map of an archive and
// only textures inside it, so triwalk writes a temporary archive whose
// only map is the chosen one, looks textures up in the game's other
// archives itself, and reads the spawn points from the map's entities.

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace triwalk {

class ZipArchive {
public:
  explicit ZipArchive(const std::filesystem::path& path);  // throws InputError
  ~ZipArchive();
  ZipArchive(const ZipArchive&) = delete;
  ZipArchive& operator=(const ZipArchive&) = delete;

  const std::filesystem::path& path() const { return path_; }
  const std::vector<std::string>& names() const { return names_; }
  bool contains(const std::string& name) const;
  std::vector<uint8_t> read(const std::string& name) const;  // throws InputError

private:
  std::filesystem::path path_;
  void* handle_ = nullptr;
  std::vector<std::string> names_;
};

// "maps/NAME.bsp" entries, as names.
std::vector<std::string> quake3Maps(const ZipArchive& archive);

// Writes an archive with every entry of source except the other maps, so
// that the chosen map is the one Assimp reads. Throws InputError naming
// the archive if the map is not in it.
void writeSingleMapArchive(const ZipArchive& source, const std::string& map, const std::filesystem::path& destination);

// Player spawn points (info_player_*) of a Quake 3 .bsp, in map units.
std::vector<glm::vec3> quake3SpawnPoints(const std::vector<uint8_t>& bsp, const std::string& subject);

// A texture named without extension (as Quake 3 surfaces name them), the
// first of .jpg, .tga, .png found in the archives.
std::optional<std::vector<uint8_t>> findQuake3Texture(const std::vector<const ZipArchive*>& archives, const std::string& name);

}  // namespace triwalk
