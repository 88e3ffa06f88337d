// Fuzzes Dataset::open: manifest.json as the fuzzer writes it, next to the
// view files of a real capture (fuzz/seeds/dataset), so that a manifest
// that parses also reaches the file checks.

#include "core/io/dataset.h"
#include "core/support/errors.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace triwalk;
  static const std::filesystem::path directory = [] {
    const std::filesystem::path path = fuzz::scratchDirectory() / "dataset";
    std::filesystem::create_directories(path);
    std::filesystem::copy(TRIWALK_FUZZ_DATASET, path, std::filesystem::copy_options::recursive |
                                                          std::filesystem::copy_options::overwrite_existing);
    return path;
  }();
  const std::filesystem::path manifest = fuzz::writeInput("dataset/manifest.json", data, size);
  try {
    const Dataset dataset = Dataset::open(manifest.parent_path());
    (void)dataset.walkableRegion();
  } catch (const InputError&) {
  }
  return 0;
}
