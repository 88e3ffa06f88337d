#pragma once
// Options shared by decimate, eval and suite: the resolution errors are
// computed at, the warp, blend and error options, and (decimate, suite)
// how references are selected.

#include "app/setup/quality_options.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection_recipe.h"
#include "core/selection/triangle_error.h"

#include <CLI/CLI.hpp>

namespace triwalk {

struct ErrorArguments {
  int width = 0;  // 0: the largest width not above kDefaultErrorWidth that divides the data set's
  std::string destinations = "centroid";
  QualityArguments quality;
};

// defaults: the command's default --holes, --blend-weights and
// --source-mesh (withSelectionDefaults for decimate, TriangleErrorSettings'
// for eval and the suite's evaluation).
void addErrorOptions(CLI::App& command, ErrorArguments& arguments, const SynthesisOptions& defaults);

// How references are selected, apart from the stopping rule (threshold
// and target), which decimate and suite set their own way.
struct SelectionArguments {
  bool oneRing = false;
  std::string cost = "served-samples";
  bool fixedBoundary = false;
  bool unweightedCost = false;
  int pricedSamples = DecimationOptions{}.pricedSamples;
  std::string recosting = recostingName(DecimationOptions{}.lazyRecosting);
  std::optional<double> refineRadius;  // none: neighbourhoodRadius
  std::optional<int> exchanges;        // none: as many as references
  double refineScreen = RefinementOptions{}.screenedShare;
  int refinePriced = RefinementOptions{}.pricedSamples;
  int errorStride = kSelectionErrorStride;  // TriangleErrorSettings::stride of the selection's errors
};

void addSelectionOptions(CLI::App& command, SelectionArguments& arguments);
SelectionSettings selectionSettings(const SelectionArguments& arguments, double maxError, int targetSamples);
TriangleErrorSettings triangleErrorSettings(const ErrorArguments& arguments, const Dataset& dataset);
// The selection's errors on the lattice --error-stride asks for; throws
// InputError naming it where the settings cannot have one (a hole fill
// needs every pixel).
void applyErrorStride(const SelectionArguments& arguments, TriangleErrorSettings& settings);
std::string describeErrorSettings(const TriangleErrorSettings& settings);

// When a decimation stops: --max-error, --relative-error, --target
// (decimate and tiles plan).
struct StoppingArguments {
  double maxError = 0.0, relativeError = 0.0;
  int target = 0;
  // The absolute threshold when none of the three is given (--preset
  // paper); 0: the relative kDefaultRelativeError.
  double presetMaxError = 0.0;
};
void addStoppingOptions(CLI::App& command, StoppingArguments& arguments);

// Every setting of a decimation, resolved for the data set from the
// options (the preset's threshold when no stopping rule is given);
// InputError for a target the data set cannot meet.
SelectionRecipe resolveSelection(const SelectionArguments& selection, const ErrorArguments& errors,
                                 const StoppingArguments& stopping, const Dataset& dataset);

// Every option of a decimation, as decimate and tiles plan take them,
// --preset first (app/setup/selection_preset.h).
struct DecimationArguments {
  std::string preset = "default";
  StoppingArguments stopping;
  SelectionArguments selection;
  ErrorArguments errors;
};
void addDecimationOptions(CLI::App& command, DecimationArguments& arguments);
SelectionRecipe resolveSelection(const DecimationArguments& arguments, const Dataset& dataset);

}  // namespace triwalk
