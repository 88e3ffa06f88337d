#pragma once
// One writer at a time for an output: a second triwalk that would write
// the same folder is refused in one line while the first is running,
// instead of both removing each other's staging folder and both
// reporting success over a mixed result.

#include <filesystem>

namespace triwalk {

class OutputLock {
public:
  // Takes an exclusive lock (flock) on a hidden file beside output
  // (".NAME.triwalk-lock"); throws InputError naming output and the
  // process that holds it. The lock goes with the process, so a killed
  // writer never leaves its output locked.
  explicit OutputLock(const std::filesystem::path& output);
  ~OutputLock();  // removes the lock file, then releases the lock
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

private:
  std::filesystem::path lockFile_;
  int descriptor_ = -1;
};

// output without a trailing separator ("cap/" is "cap"), so names beside
// it are formed from its last component.
std::filesystem::path withoutTrailingSeparator(const std::filesystem::path& output);

}  // namespace triwalk
