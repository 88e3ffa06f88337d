#include "core/io/atomic_file.h"

#include "core/support/errors.h"

#include <atomic>
#include <fstream>
#include <sstream>
#include <system_error>

#include <unistd.h>

namespace triwalk {

namespace {

std::filesystem::path temporarySibling(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return temporary;
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write) {
  if (path.has_parent_path() && !std::filesystem::is_directory(path.parent_path())) {
    throw InputError(path.string(), "cannot write: directory " + path.parent_path().string() + " does not exist");
  }
  const std::filesystem::path temporary = temporarySibling(path);
  try {
    write(temporary);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw InputError(path.string(), "cannot write: rename failed");
  }
}

void writeTextFileAtomically(const std::filesystem::path& path, const std::string& text) {
  writeFileAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream stream(temporary, std::ios::binary);
    stream << text;
    stream.close();
    if (!stream) throw InputError(path.string(), "cannot write file");
  });
}

std::string readTextFile(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path.string(), "cannot open file (missing or unreadable)");
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

}  // namespace triwalk
