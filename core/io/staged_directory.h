#pragma once
// An output folder built beside its destination and moved into place only
// when complete, so an error or Ctrl-C never leaves a half-written data
// set where a whole one is expected, and an earlier run's files never
// stay beside this run's: the destination is replaced as a whole.

#include "core/io/output_lock.h"

#include <filesystem>
#include <functional>
#include <string>

namespace triwalk {

class StagedDirectory {
public:
  // Refuses (InputError) a destination that another triwalk is writing
  // (OutputLock), and one that exists, is not empty and does not hold
  // ownMarker (e.g. manifest.json: a data set it may replace; `kind` names
  // such a folder in the message, "a triwalk data set"); with an empty
  // marker any non-empty destination is refused.
  StagedDirectory(std::filesystem::path destination, const std::string& ownMarker, const std::string& kind = "");
  ~StagedDirectory();  // removes the staging folder unless committed
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  const std::filesystem::path& path() const { return staging_; }
  // Calls write(path() / name); a failure (InputError) is reported under
  // the name the file would have had in the destination, not the staging
  // folder's, which is gone by the time the user reads the message.
  void writeFile(const std::string& name, const std::function<void(const std::filesystem::path&)>& write) const;
  // Replaces the destination with the staging folder.
  void commit();

private:
  std::filesystem::path destination_;
  OutputLock lock_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace triwalk
