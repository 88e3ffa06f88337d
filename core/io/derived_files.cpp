#include "core/io/derived_files.h"

#include "core/io/atomic_file.h"
#include "core/support/errors.h"

#include <cstring>
#include <limits>
#include <fstream>
#include <iostream>

namespace triwalk {

DerivedFiles::DerivedFiles(std::filesystem::path folder, std::string kind)
    : folder_(std::move(folder)), kind_(std::move(kind)) {}

std::optional<DerivedFile> DerivedFiles::read(const std::filesystem::path& path, const std::array<char, 8>& magic,
                                              uint64_t key) const {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return std::nullopt;
  DerivedFile file{};
  try {
    file.bytes = readTextFile(path, std::numeric_limits<std::uintmax_t>::max());  // our own cache, any size
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (file.bytes.size() < sizeof(DerivedFileHeader)) return std::nullopt;
  std::memcpy(&file.header, file.bytes.data(), sizeof(DerivedFileHeader));
  if (file.header.magic != magic || file.header.key != key) return std::nullopt;
  return file;
}

void DerivedFiles::write(const std::filesystem::path& path, const DerivedFileHeader& header,
                         std::initializer_list<std::span<const std::byte>> parts) {
  try {
    {
      std::lock_guard lock(directories_);
      std::filesystem::create_directories(path.parent_path());
    }
    writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
      std::ofstream stream(temporary, std::ios::binary);
      stream.write(reinterpret_cast<const char*>(&header), sizeof(header));
      for (const std::span<const std::byte> part : parts) {
        if (part.empty()) continue;  // data() may be null
        stream.write(reinterpret_cast<const char*>(part.data()), std::streamsize(part.size()));
      }
      stream.close();
      if (!stream) throw InputError(path.string(), "cannot write file");
    });
  } catch (const std::exception& failure) {
    if (!warned_.exchange(true)) {
      std::cerr << "triwalk: " << kind_ << " are not kept (" << failure.what() << "); they will be computed again next time\n";
    }
  }
}

}  // namespace triwalk
