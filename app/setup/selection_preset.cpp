#include "app/setup/selection_preset.h"

#include "app/setup/decimation_options.h"
#include "core/support/errors.h"

namespace triwalk {

namespace {

// The paper's rules (docs/DESIGN.md, "Departures from the paper"), as far
// as triwalk has them: the blend interval stays triwalk's, relative to the
// nearest distance (the only interval triwalk has), the errors are measured
// at the error width, and the warp stays the mesh warp: the literal point
// warp is not the paper's splats and leaves cracks at every magnification,
// so its errors are not on the paper's scale (on the main job no collapse
// costs under 1.85 with it: the cheapest 13.1).
void applyPaperRules(DecimationArguments& arguments) {
  SelectionArguments& selection = arguments.selection;
  selection.cost = "centroid";  // keeps the hull: the centroid cost implies the fixed boundary
  selection.unweightedCost = true;
  selection.recosting = "eager";
  selection.refineRadius = 0.0;
  selection.exchanges = 0;
  QualityArguments& quality = arguments.errors.quality;
  quality.blendWeights = "distance";
  quality.holes = "black";
  quality.pixelWeighting = "uniform";
  arguments.errors.destinations = "centroid";
  arguments.stopping.presetMaxError = kPaperMaxError;
}

}  // namespace

void applyPreset(const std::string& name, DecimationArguments& arguments) {
  if (name == "default") return;
  if (name == "paper") {
    applyPaperRules(arguments);
  } else if (name == "fast") {
    arguments.selection.errorStride = 2;
  } else {
    throw InputError("--preset", "unknown preset '" + name + "' (use default, paper or fast)");
  }
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
