#include "tests/test_support.h"

#include <atomic>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace triwalk::testing {

TemporaryDirectory::TemporaryDirectory() {
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("triwalk-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TemporaryDirectory::~TemporaryDirectory() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

size_t countEntries(const std::filesystem::path& folder, const std::string& prefix) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) return 0;
  size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    count += entry.path().filename().string().starts_with(prefix);
  }
  return count;
}

std::string readTextFileOrEmpty(const std::filesystem::path& path) {
  std::ifstream stream(path);
  return std::string(std::istreambuf_iterator<char>(stream), {});
}

void requireInputError(const std::function<void()>& action, const std::string& subject, const std::string& problem) {
  try {
    action();
  } catch (const InputError& error) {
    const std::string message = error.what();
    INFO("message: " << message);
    CHECK(message.find(subject) != std::string::npos);
    CHECK(message.find(problem) != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
    return;
  }
  FAIL("expected an InputError naming " << subject << " with '" << problem << "'");
}

std::vector<glm::dvec2> unitGrid(int columns, int rows) {
  std::vector<glm::dvec2> points;
  for (int x = 0; x < columns; ++x) {
    for (int y = 0; y < rows; ++y) points.emplace_back(double(x), double(y));
  }
  return points;
}

}  // namespace triwalk::testing
