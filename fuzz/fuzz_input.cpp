#include "fuzz/fuzz_input.h"

#include <unistd.h>

#include <fstream>
#include <string>

namespace triwalk::fuzz {

const std::filesystem::path& scratchDirectory() {
  static const std::filesystem::path directory = [] {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / ("triwalk-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return directory;
}

std::filesystem::path writeInput(std::string_view name, const uint8_t* data, size_t size) {
  const std::filesystem::path path = scratchDirectory() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

}  // namespace triwalk::fuzz
