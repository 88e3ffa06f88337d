// Fuzzes readTileOutcome: any bytes as tile 0's file beside the seed plan
// of fuzz/seeds/tile_plan over the capture in fuzz/seeds/dataset. A tile's
// file names its plan by a hash of plan.json, and a file naming another
// plan is skipped unread, so the harness writes that hash where the input
// says PLANKEY (as the seeds do): the fuzzer then reaches the fields past it.

#include "core/io/dataset.h"
#include "core/selection/tile_files.h"
#include "core/support/errors.h"
#include "fuzz/fuzz_input.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace triwalk;
  static const Dataset dataset = Dataset::open(TRIWALK_FUZZ_DATASET);
  static const std::filesystem::path folder = [] {
    const std::filesystem::path made = fuzz::scratchDirectory() / "outcome";
    std::filesystem::create_directories(made);
    std::filesystem::copy_file(std::filesystem::path(TRIWALK_FUZZ_DATASET).parent_path() / "tile_plan" / "plan.json",
                               made / "plan.json", std::filesystem::copy_options::overwrite_existing);
    return made;
  }();
  static const TilePlan plan = readTilePlan(folder, dataset);
  std::string text(reinterpret_cast<const char*>(data), size);
  for (size_t at = text.find("PLANKEY"); at != std::string::npos; at = text.find("PLANKEY", at + plan.key.size())) {
    text.replace(at, 7, plan.key);
  }
  fuzz::writeInput("outcome/tile_0000.json", reinterpret_cast<const uint8_t*>(text.data()), text.size());
  try {
    (void)readTileOutcome(folder, 0, plan, dataset);
  } catch (const InputError&) {
  }
  return 0;
}
