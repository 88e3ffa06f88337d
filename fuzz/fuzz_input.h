#pragma once
// What every harness shares: the fuzzer's bytes as a file in a private
// scratch folder (the readers under test read paths, as the commands do),
// and the rule for what counts as a finding.
//
// A reader may refuse its input only with InputError (one line naming the
// file). Any other exception, a crash, a hang or a leak is a finding: the
// harness lets it escape to libFuzzer.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace triwalk::fuzz {

// A folder under the system temp dir, one per process, made on first use.
const std::filesystem::path& scratchDirectory();
// Writes the bytes to name inside the scratch folder and returns its path.
std::filesystem::path writeInput(std::string_view name, const uint8_t* data, size_t size);

}  // namespace triwalk::fuzz
