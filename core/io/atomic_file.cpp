#include "core/io/atomic_file.h"

#include "core/support/errors.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
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
    // Every step checked, the close too: a full disk may only show there.
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) throw InputError(path.string(), std::string("cannot write file: ") + std::strerror(errno));
    const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size() && std::fflush(file) == 0;
    const int writeError = errno;
    if (std::fclose(file) != 0 || !written) {
      throw InputError(path.string(), std::string("cannot write file: ") + std::strerror(written ? errno : writeError));
    }
  });
}

std::string readTextFile(const std::filesystem::path& path, std::uintmax_t maxBytes) {
  // status() follows symlinks: a link to /dev/zero, a FIFO or a device is
  // refused here instead of being read forever (or waited on).
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw InputError(path.string(), "file does not exist");
  if (!std::filesystem::is_regular_file(status)) throw InputError(path.string(), "is not a regular file");
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) throw InputError(path.string(), "cannot read file size: " + error.message());
  if (size > maxBytes) {
    throw InputError(path.string(), "is " + std::to_string(size >> 20) + " MiB; triwalk reads such files up to " +
                                        std::to_string(maxBytes >> 20) + " MiB");
  }
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path.string(), "cannot open file (missing or unreadable)");
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

}  // namespace triwalk
