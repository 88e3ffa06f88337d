#include "scene/quake3_archive.h"

#include "core/support/errors.h"

#include <minizip/unzip.h>
#include <minizip/zip.h>

#include <algorithm>
#include <cstring>
#include <sstream>

namespace triwalk {

ZipArchive::ZipArchive(const std::filesystem::path& path) : path_(path) {
  if (!std::filesystem::exists(path)) throw InputError(path.string(), "file does not exist");
  handle_ = unzOpen64(path.string().c_str());
  if (!handle_) throw InputError(path.string(), "not a readable zip (pk3) archive");
  for (int status = unzGoToFirstFile(handle_); status == UNZ_OK; status = unzGoToNextFile(handle_)) {
    char name[1024];
    unz_file_info64 info{};
    if (unzGetCurrentFileInfo64(handle_, &info, name, sizeof name, nullptr, 0, nullptr, 0) == UNZ_OK) names_.push_back(name);
  }
}

ZipArchive::~ZipArchive() {
  if (handle_) unzClose(handle_);
}

bool ZipArchive::contains(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

std::vector<uint8_t> ZipArchive::read(const std::string& name) const {
  if (unzLocateFile(handle_, name.c_str(), 0) != UNZ_OK) throw InputError(path_.string(), "no entry " + name);
  unz_file_info64 info{};
  unzGetCurrentFileInfo64(handle_, &info, nullptr, 0, nullptr, 0, nullptr, 0);
  std::vector<uint8_t> bytes(size_t(info.uncompressed_size));
  if (unzOpenCurrentFile(handle_) != UNZ_OK) throw InputError(path_.string(), "cannot open entry " + name);
  const int read = unzReadCurrentFile(handle_, bytes.data(), unsigned(bytes.size()));
  unzCloseCurrentFile(handle_);
  if (read != int(bytes.size())) throw InputError(path_.string(), "entry " + name + " is truncated or corrupt");
  return bytes;
}

std::vector<std::string> quake3Maps(const ZipArchive& archive) {
  std::vector<std::string> maps;
  for (const std::string& name : archive.names()) {
    if (name.rfind("maps/", 0) == 0 && name.size() > 9 && name.substr(name.size() - 4) == ".bsp") {
      maps.push_back(name.substr(5, name.size() - 9));
    }
  }
  return maps;
}

void writeSingleMapArchive(const ZipArchive& source, const std::string& map, const std::filesystem::path& destination) {
  const std::string entry = "maps/" + map + ".bsp";
  if (!source.contains(entry)) {
    std::string available;
    for (const std::string& name : quake3Maps(source)) available += (available.empty() ? "" : ", ") + name;
    throw InputError(source.path().string(), "no map '" + map + "' (it has: " + available + ")");
  }
  zipFile zip = zipOpen64(destination.string().c_str(), APPEND_STATUS_CREATE);
  if (!zip) throw InputError(destination.string(), "cannot create temporary archive");
  bool ok = true;
  for (const std::string& name : source.names()) {
    const bool otherMap = name.rfind("maps/", 0) == 0 && name != entry;
    if (otherMap || name.back() == '/') continue;
    const std::vector<uint8_t> bytes = source.read(name);
    zip_fileinfo info{};
    ok &= zipOpenNewFileInZip64(zip, name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr, 0, 0, 0) == ZIP_OK;
    ok &= zipWriteInFileInZip(zip, bytes.data(), unsigned(bytes.size())) == ZIP_OK;
    ok &= zipCloseFileInZip(zip) == ZIP_OK;
  }
  ok &= zipClose(zip, nullptr) == ZIP_OK;
  if (!ok) throw InputError(destination.string(), "cannot write temporary archive");
}

std::vector<glm::vec3> quake3SpawnPoints(const std::vector<uint8_t>& bsp, const std::string& subject) {
  // Header: "IBSP", version, then 17 lumps of (offset, length); lump 0 is
  // the entity text: { "key" "value" ... } blocks.
  auto read32 = [&](size_t at) {
    int32_t value = 0;
    std::memcpy(&value, bsp.data() + at, 4);
    return value;
  };
  if (bsp.size() < 8 + 17 * 8 || std::memcmp(bsp.data(), "IBSP", 4) != 0) {
    throw InputError(subject, "not a Quake 3 BSP (no IBSP header)");
  }
  const int32_t offset = read32(8), length = read32(12);
  if (offset < 0 || length < 0 || size_t(offset) + size_t(length) > bsp.size()) throw InputError(subject, "corrupt entity lump");
  std::istringstream text(std::string(reinterpret_cast<const char*>(bsp.data()) + offset, size_t(length)));
  std::vector<glm::vec3> spawns;
  std::string key, classname, origin;
  bool inEntity = false;
  auto readQuoted = [&](std::string& out) {
    out.clear();
    char c;
    while (text.get(c) && c != '"') out += c;
  };
  char c;
  while (text.get(c)) {
    if (c == '{') {
      inEntity = true;
      classname.clear();
      origin.clear();
    } else if (c == '}') {
      if (inEntity && classname.rfind("info_player", 0) == 0 && !origin.empty()) {
        glm::vec3 p;
        std::istringstream values(origin);
        if (values >> p.x >> p.y >> p.z) spawns.push_back(p);
      }
      inEntity = false;
    } else if (c == '"' && inEntity) {
      readQuoted(key);
      while (text.get(c) && c != '"') {
      }
      std::string value;
      readQuoted(value);
      if (key == "classname") classname = value;
      if (key == "origin") origin = value;
    }
  }
  return spawns;
}

std::optional<std::vector<uint8_t>> findQuake3Texture(const std::vector<const ZipArchive*>& archives, const std::string& name) {
  for (const char* extension : {".jpg", ".tga", ".png"}) {
    for (const ZipArchive* archive : archives) {
      if (archive->contains(name + extension)) return archive->read(name + extension);
    }
  }
  return std::nullopt;
}

}  // namespace triwalk
