#pragma once
// Helpers shared by the test suites: scratch directories, checks that an
// InputError names the right file, sample layouts.

#include "core/support/errors.h"

#include <doctest/doctest.h>
#include <glm/vec2.hpp>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace triwalk::testing {

// A fresh directory under the system temp dir, removed with its contents.
class TemporaryDirectory {
public:
  TemporaryDirectory();
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

private:
  std::filesystem::path path_;
};

// The entries of folder whose names start with prefix (0 when it is not a folder).
size_t countEntries(const std::filesystem::path& folder, const std::string& prefix);

// The file's text, or an empty string if it cannot be read.
std::string readTextFileOrEmpty(const std::filesystem::path& path);

// Runs action, which must throw InputError whose one-line message contains
// both the expected subject (a file name) and the expected problem text.
void requireInputError(const std::function<void()>& action, const std::string& subject, const std::string& problem);

// Whether two numbers have the same bits (so +0 and -0 differ, and a NaN
// may equal itself).
inline bool sameBits(float a, float b) {
  return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b);
}
inline bool sameBits(double a, double b) {
  return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
}

// Sample x * rows + y at (x, y), 1 m apart.
std::vector<glm::dvec2> unitGrid(int columns, int rows);

}  // namespace triwalk::testing
