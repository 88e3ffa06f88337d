#include "core/io/staged_directory.h"

#include "core/support/errors.h"

#include <system_error>

#include <unistd.h>

namespace triwalk {

namespace {

const std::string kStagingSuffix = ".partial-triwalk-";

// A name of this process's own, so that nothing another run does (before
// the lock, or a run killed before it could clean up) touches it.
std::filesystem::path stagingName(const std::filesystem::path& destination) {
  return destination.string() + kStagingSuffix + std::to_string(::getpid());
}

// Staging folders of earlier runs of this output that were killed before
// they could remove their own: safe to remove while the lock is held.
void removeAbandonedStaging(const std::filesystem::path& destination) {
  std::error_code error;
  const std::string prefix = destination.filename().string() + kStagingSuffix;
  const std::filesystem::path parent = destination.has_parent_path() ? destination.parent_path() : ".";
  for (const auto& entry : std::filesystem::directory_iterator(parent, error)) {
    if (entry.path().filename().string().starts_with(prefix)) std::filesystem::remove_all(entry.path(), error);
  }
}

}  // namespace

StagedDirectory::StagedDirectory(std::filesystem::path destination, const std::string& ownMarker, const std::string& kind)
    : destination_(withoutTrailingSeparator(destination)), lock_(destination_), staging_(stagingName(destination_)) {
  if (std::filesystem::exists(destination_) && !std::filesystem::is_empty(destination_) &&
      (ownMarker.empty() || !std::filesystem::exists(destination_ / ownMarker))) {
    throw InputError(destination_.string(), ownMarker.empty() ? "exists and is not empty; refusing to overwrite it"
                                                              : "exists and is not " + kind + "; refusing to overwrite it");
  }
  removeAbandonedStaging(destination_);
  std::error_code error;
  std::filesystem::create_directories(staging_, error);
  if (error) throw InputError(staging_.string(), "cannot create directory: " + error.message());
}

void StagedDirectory::writeFile(const std::string& name,
                                const std::function<void(const std::filesystem::path&)>& write) const {
  try {
    write(staging_ / name);
  } catch (const InputError& error) {
    throw InputError((destination_ / name).string(), error.problem());
  }
}

StagedDirectory::~StagedDirectory() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove_all(staging_, ignored);
}

void StagedDirectory::commit() {
  std::error_code error;
  // An existing destination steps aside first and is removed only once the new folder is in place.
  const std::filesystem::path old = destination_.string() + ".old-triwalk";
  const bool replacing = std::filesystem::exists(destination_);
  if (replacing) {
    std::filesystem::remove_all(old, error);
    std::filesystem::rename(destination_, old, error);
    if (error) throw InputError(destination_.string(), "cannot replace the existing folder: " + error.message());
  }
  std::filesystem::rename(staging_, destination_, error);
  if (error) throw InputError(destination_.string(), "cannot move the new folder into place: " + error.message());
  if (replacing) std::filesystem::remove_all(old, error);
  committed_ = true;
}

}  // namespace triwalk
