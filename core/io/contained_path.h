#pragma once
// Paths that a data set names (a manifest's image files) are read only
// inside the data set: a manifest must not make triwalk open /etc/passwd,
// a FIFO that blocks forever, or an EXR in someone else's folder.

#include <filesystem>
#include <string>

namespace triwalk {

// The regular file `entry` names inside `directory`. Throws InputError
// naming `subject` (the manifest and the entry) unless `entry` is a
// non-empty relative path that stays inside the directory after
// normalisation and after following symlinks, and is a regular file.
std::filesystem::path containedFile(const std::filesystem::path& directory, const std::string& entry,
                                    const std::string& subject);

// Throws InputError naming path unless it lies inside directory after
// following symlinks (the same rule for a capture folder being imported
// as for a data set being read).
void requireInside(const std::filesystem::path& directory, const std::filesystem::path& path, const std::string& what);

}  // namespace triwalk
