#include "core/io/output_lock.h"

#include "core/support/errors.h"

#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace triwalk {

std::filesystem::path withoutTrailingSeparator(const std::filesystem::path& output) {
  std::filesystem::path path = output.lexically_normal();
  return path.has_filename() || !path.has_parent_path() ? path : path.parent_path();
}

namespace {

std::string holderOf(int descriptor) {
  char text[32] = {};
  const ssize_t length = ::pread(descriptor, text, sizeof text - 1, 0);
  return length > 0 ? " (process " + std::string(text, size_t(length)) + ")" : "";
}

}  // namespace

OutputLock::OutputLock(const std::filesystem::path& output) {
  const std::filesystem::path path = withoutTrailingSeparator(output);
  lockFile_ = path.parent_path() / ("." + path.filename().string() + ".triwalk-lock");
  // An output may be made in folders that do not exist yet (the command line checked they can be).
  std::error_code ignored;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ignored);
  // The holder removes the file before it lets go, so a file locked here
  // may already be unlinked: lock again until the file locked is the one
  // the name leads to.
  for (;;) {
    descriptor_ = ::open(lockFile_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (descriptor_ < 0) {
      throw InputError(path.string(), "cannot create the lock file " + lockFile_.string() + ": " + std::strerror(errno));
    }
    if (::flock(descriptor_, LOCK_EX | LOCK_NB) != 0) {
      const std::string holder = holderOf(descriptor_);
      ::close(descriptor_);
      throw InputError(path.string(), "another triwalk is writing this output" + holder +
                                          "; wait for it to finish or choose another output");
    }
    struct stat locked {}, named {};
    if (::fstat(descriptor_, &locked) == 0 && ::stat(lockFile_.c_str(), &named) == 0 && locked.st_ino == named.st_ino &&
        locked.st_dev == named.st_dev) {
      break;
    }
    ::close(descriptor_);
  }
  const std::string pid = std::to_string(::getpid());
  // Should this fail, only a refused second writer's message misses the number.
  [[maybe_unused]] const bool noted =
      ::ftruncate(descriptor_, 0) == 0 && ::pwrite(descriptor_, pid.data(), pid.size(), 0) == ssize_t(pid.size());
}

OutputLock::~OutputLock() {
  ::unlink(lockFile_.c_str());
  ::close(descriptor_);
}

}  // namespace triwalk
