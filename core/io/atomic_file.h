#pragma once
// Every output file is written to a temporary name beside it and renamed
// into place, so a crash or Ctrl-C never leaves a partial file behind.

#include "core/support/input_limits.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace triwalk {

// Calls write(temporaryPath), then renames it onto path. If write throws,
// the temporary file is removed and the exception propagates.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write);

void writeTextFileAtomically(const std::filesystem::path& path, const std::string& text);

// A regular file (symlinks followed) of at most maxBytes; InputError
// naming the path for a missing, special (FIFO, device) or larger file.
std::string readTextFile(const std::filesystem::path& path, std::uintmax_t maxBytes = kMaxTextFileBytes);

}  // namespace triwalk
