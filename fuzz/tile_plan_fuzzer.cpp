// Fuzzes readTilePlan against the real capture in fuzz/seeds/dataset, and
// the recipe a plan's tiles run with (its settings read as `tiles run` and
// `tiles stitch` read them), both of which come before any view is read.

#include "core/io/dataset.h"
#include "core/io/json_fields.h"
#include "core/selection/selection_recipe.h"
#include "core/selection/tile_files.h"
#include "core/support/errors.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace triwalk;
  static const Dataset dataset = Dataset::open(TRIWALK_FUZZ_DATASET);
  static const std::filesystem::path folder = [] {
    std::filesystem::create_directories(fuzz::scratchDirectory() / "plan");
    return fuzz::scratchDirectory() / "plan";
  }();
  fuzz::writeInput("plan/plan.json", data, size);
  try {
    const TilePlan plan = readTilePlan(folder, dataset);
    (void)readSelectionRecipe(JsonObject(plan.settings, "tile plan", "settings"), dataset);
  } catch (const InputError&) {
  }
  return 0;
}
