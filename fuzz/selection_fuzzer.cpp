// Fuzzes readSelection against the real capture in fuzz/seeds/dataset
// (whose ids and positions a selection must match).

#include "core/io/dataset.h"
#include "core/selection/selection.h"
#include "core/support/errors.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace triwalk;
  static const Dataset dataset = Dataset::open(TRIWALK_FUZZ_DATASET);
  const std::filesystem::path path = fuzz::writeInput("selection.json", data, size);
  try {
    (void)readSelection(path, dataset);
  } catch (const InputError&) {
  }
  return 0;
}
