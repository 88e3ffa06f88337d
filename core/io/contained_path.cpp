#include "core/io/contained_path.h"

#include "core/support/errors.h"

#include <algorithm>

namespace triwalk {

namespace {

bool isInside(const std::filesystem::path& root, const std::filesystem::path& path) {
  const auto [rootEnd, pathAt] = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
  return rootEnd == root.end() && pathAt != path.end();
}

}  // namespace

void requireInside(const std::filesystem::path& directory, const std::filesystem::path& path, const std::string& what) {
  std::error_code error;
  const std::filesystem::path root = std::filesystem::canonical(directory, error);
  const std::filesystem::path target = error ? std::filesystem::path() : std::filesystem::canonical(path, error);
  if (error || !isInside(root, target)) {
    throw InputError(path.string(), what + " leads outside " + directory.string() + " (symlink)");
  }
}

std::filesystem::path containedFile(const std::filesystem::path& directory, const std::string& entry,
                                    const std::string& subject) {
  const std::string quoted = "'" + entry + "'";
  if (entry.empty()) throw InputError(subject, "empty file name");
  const std::filesystem::path relative(entry);
  if (relative.is_absolute() || relative.has_root_name() || relative.has_root_directory()) {
    throw InputError(subject, "file " + quoted + " is absolute; files must be relative to the data set");
  }
  const std::filesystem::path normal = relative.lexically_normal();
  if (normal.empty() || *normal.begin() == ".." || normal == ".") {
    throw InputError(subject, "file " + quoted + " leaves the data set folder");
  }
  const std::filesystem::path path = directory / normal;
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) throw InputError(subject, "file " + quoted + " does not exist");
  // Symlinks are followed: where they end up must still be inside.
  const std::filesystem::path root = std::filesystem::canonical(directory, error);
  const std::filesystem::path target = error ? std::filesystem::path() : std::filesystem::canonical(path, error);
  if (error || !isInside(root, target)) {
    throw InputError(subject, "file " + quoted + " leads outside the data set folder (symlink)");
  }
  if (!std::filesystem::is_regular_file(status)) throw InputError(subject, "file " + quoted + " is not a regular file");
  return path;
}

}  // namespace triwalk
