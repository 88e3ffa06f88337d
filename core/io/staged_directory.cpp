#include "core/io/staged_directory.h"

#include "core/support/errors.h"

#include <system_error>

namespace triwalk {

StagedDirectory::StagedDirectory(std::filesystem::path destination, const std::string& ownMarker)
    : destination_(std::move(destination)), staging_(destination_.string() + ".partial-triwalk") {
  if (std::filesystem::exists(destination_) && !std::filesystem::is_empty(destination_) &&
      (ownMarker.empty() || !std::filesystem::exists(destination_ / ownMarker))) {
    throw InputError(destination_.string(), ownMarker.empty() ? "exists and is not empty; refusing to overwrite it"
                                                              : "exists and is not a triwalk data set; refusing to overwrite it");
  }
  std::error_code error;
  std::filesystem::remove_all(staging_, error);
  std::filesystem::create_directories(staging_, error);
  if (error) throw InputError(staging_.string(), "cannot create directory: " + error.message());
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
