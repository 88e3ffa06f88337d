#include "app/setup/selection_preset.h"

#include "app/setup/decimation_options.h"
#include "core/support/errors.h"

namespace triwalk {

// The paper's rules (docs/DESIGN.md, "Departures from the paper"), as far
// as triwalk has them: the blend interval stays triwalk's, relative to the
// nearest distance (the only interval triwalk has), the errors are measured
// at the error width, and the warp stays the mesh warp: the literal point
// warp is not the paper's splats and leaves cracks at every magnification,
// so its errors are not on the paper's scale (on the main job no collapse
// costs under 1.85 with it: the cheapest 13.1).
void applySelectionPreset(const std::string& name, SelectionArguments& selection) {
  if (name == "paper") {
    selection.cost = "centroid";  // keeps the hull: the centroid cost implies the fixed boundary
    selection.unweightedCost = true;
    selection.recosting = "eager";
    selection.refineRadius = 0.0;
    selection.exchanges = 0;
  } else if (name == "fast") {
    selection.errorStride = 2;
  } else if (name != "default") {
    throw InputError("--preset", "unknown preset '" + name + "' (use default, paper or fast)");
  }
}

void applyPresetErrorRules(const std::string& name, ErrorArguments& errors) {
  if (name != "paper") return;
  errors.quality.blendWeights = "distance";
  errors.quality.holes = "black";
  errors.quality.pixelWeighting = "uniform";
  errors.destinations = "centroid";
}

void applyPreset(const std::string& name, DecimationArguments& arguments) {
  applySelectionPreset(name, arguments.selection);
  applyPresetErrorRules(name, arguments.errors);
  if (name == "paper") arguments.stopping.presetMaxError = kPaperMaxError;
  arguments.preset = name;
}

void addPresetOption(CLI::App& command, DecimationArguments& arguments) {
  command
      .add_option_function<std::string>(
          "--preset", [&arguments](const std::string& name) { applyPreset(name, arguments); },
          "Where every setting starts; options given beside it change one setting each. default: triwalk's. "
          "paper: the paper's rules, to reproduce its Table 1 (centroid collapse cost, unweighted, hull kept, no "
          "refinement, inverse-distance weights, raw holes, uniform pixel weights, --max-error 1.85 "
          "unless a stopping option is given). fast: the selection's errors on every other row and column "
          "(--error-stride 2): 0.34x the decimation's time, probe error +2.9% +- 1.3% on held-out levels "
          "(docs/BENCHMARKS.md)")
      ->check(CLI::IsMember({"default", "paper", "fast"}));
}

}  // namespace triwalk
