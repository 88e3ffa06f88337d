#include "app/setup/decimation_options.h"

#include "app/setup/option_checks.h"
#include "app/setup/selection_preset.h"
#include "core/support/errors.h"

#include <cstdio>

namespace triwalk {

void addErrorOptions(CLI::App& command, ErrorArguments& arguments, const SynthesisOptions& defaults) {
  arguments.quality.blendWeights = blendWeightsName(defaults.blend.weights);
  arguments.quality.sourceMesh = sourceMeshName(defaults.warp.mesh);
  command.add_option("--error-width", arguments.width,
                     "Panorama width errors are computed at (divides the data set's width; default: the largest such "
                     "width not above " + std::to_string(kDefaultErrorWidth) + ")")
      ->check(nonNegativeNumber());
  command.add_option("--triangle-destinations", arguments.destinations,
                     "Where a triangle's error is measured: centroid (the paper's), quadrature (centroid and the "
                     "three sub-triangle centroids) or interior (up to 8 samples inside it)")
      ->capture_default_str()->check(CLI::IsMember({"centroid", "quadrature", "interior"}));
  addQualityOptions(command, arguments.quality, defaults.holes);
}

TriangleErrorSettings triangleErrorSettings(const ErrorArguments& arguments, const Dataset& dataset) {
  TriangleErrorSettings settings;
  settings.width = namingOption("error_width", "--error-width", [&] { return errorWidthFor(dataset, arguments.width); });
  settings.destinations = parseTriangleDestinations(arguments.destinations);
  settings.synthesis = synthesisOptions(arguments.quality);
  settings.error = errorOptions(arguments.quality);
  return settings;
}

void applyErrorStride(const SelectionArguments& arguments, TriangleErrorSettings& settings) {
  settings.stride = arguments.errorStride;
  checkErrorStride(settings, "--error-stride", "--holes");
}

std::string describeErrorSettings(const TriangleErrorSettings& settings) {
  return describeErrorPanorama(settings.width, settings.stride) + ", " + triangleDestinationsName(settings.destinations) +
         " destinations; " + describeQuality(settings.synthesis, settings.error);
}

void addSelectionOptions(CLI::App& command, SelectionArguments& arguments) {
  command.add_option("--cost", arguments.cost,
                     "What ranks collapses: served-samples (the increase of the error over the dense samples the "
                     "changed triangles serve) or centroid (the paper's: the mean error of the new triangles, each "
                     "at the sample nearest its centroid)")
      ->capture_default_str()->check(CLI::IsMember({"served-samples", "centroid"}));
  command.add_flag("--fixed-boundary", arguments.fixedBoundary,
                   "With --cost served-samples: keep the paper's rule that the covered region never shrinks "
                   "(default: the boundary may move inward; samples left outside are served by the nearest triangle)");
  command.add_flag("--one-ring", arguments.oneRing, "Also try every free sample inside the two one-rings as the placement");
  command.add_flag("--unweighted-cost", arguments.unweightedCost,
                   "With --cost centroid: the paper's plain mean of the new triangles' errors (default: area-weighted)");
  command
      .add_option("--priced-samples", arguments.pricedSamples,
                  "With --cost served-samples: price each collapse from at most this many of the samples its "
                  "triangles serve (a fixed random subset of each triangle's, scaled up), besides the references it "
                  "frees; 0: all")
      ->capture_default_str()
      ->check(nonNegativeNumber());
  command
      .add_option("--recosting", arguments.recosting,
                  "After a collapse: eager (cost every edge it changed at once) or lazy (only the placement's; "
                  "the others are costed again when they reach the top of the queue)")
      ->capture_default_str()
      ->check(CLI::IsMember({"eager", "lazy"}));
  command.add_option("--refine-radius", arguments.refineRadius,
                     "After decimation, move references up to this far (metres) at a time while that lowers the "
                     "mean error over the dense samples; 0 disables (default: to any of the 8 nearest samples, "
                     "1.01 x the lower quartile of the distance to the 8th nearest)")
      ->check(nonNegativeNumber());
  command.add_option("--exchanges", arguments.exchanges,
                     "At most this many exchanges in the refinement, a reference anywhere for a free sample anywhere "
                     "(default: as many as there are references; 0: local moves only)")
      ->check(nonNegativeNumber());
  command
      .add_option("--refine-screen", arguments.refineScreen,
                  "Share of the dense samples (a fixed random subset) the refinement ranks candidate moves on "
                  "before scoring the best few on all of them (faster, and it misses moves: see docs/history/RESULTS-2026-11.md); 0: "
                  "every candidate on all of them")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  command
      .add_option("--refine-priced", arguments.refinePriced,
                  "Without --refine-screen: price each local move of the refinement on about this many of the "
                  "samples whose triangle it changes (a fixed random subset of each new triangle's, against their "
                  "errors now), price again on 4 times as many those within two standard errors of the selection, "
                  "and score on all of them only those still within (the exchange search: its single removals and "
                  "insertions, the same way for those that may rank among the lowest); 0: every candidate on all "
                  "of them")
      ->capture_default_str()
      ->check(nonNegativeNumber());
  command
      .add_option("--error-stride", arguments.errorStride,
                  "Compute the selection's errors on every N-th row and column of the error panorama (the same "
                  "pixels the whole one has there, a quarter of them at 2); 1: every pixel. Judging a selection "
                  "(eval, the suite's evaluation) always reads every pixel")
      ->capture_default_str()
      ->check(errorStride());
}

SelectionSettings selectionSettings(const SelectionArguments& arguments, double maxError, int targetSamples) {
  SelectionSettings settings;
  DecimationOptions& options = settings.decimation;
  options.maxError = maxError;
  options.targetSamples = targetSamples;
  options.oneRingCandidates = arguments.oneRing;
  options.cost = parseCollapseCost(arguments.cost);
  options.fixedBoundary = arguments.fixedBoundary || options.cost == CollapseCost::Centroid;
  options.areaWeightedCost = !arguments.unweightedCost;
  options.pricedSamples = arguments.pricedSamples;
  options.lazyRecosting = parseLazyRecosting(arguments.recosting);
  settings.refinement.radius = arguments.refineRadius;
  settings.refinement.maxExchanges = arguments.exchanges;
  settings.refinement.screenedShare = arguments.refineScreen;
  settings.refinement.pricedSamples = arguments.refinePriced;
  return settings;
}

void addStoppingOptions(CLI::App& command, StoppingArguments& arguments) {
  CLI::Option* maxError = command.add_option(
      "--max-error", arguments.maxError,
      "Stop before a collapse whose error exceeds this absolute value (the paper's 1.85; up to 1e9, above any error, "
      "which the selection file can hold)")
      ->check(within(kMaxErrorRange));
  char relativeHelp[400];
  std::snprintf(relativeHelp, sizeof relativeHelp,
                "Stop before a collapse whose error exceeds this many times the dense triangulation's mean triangle error "
                "(default %.2f, the paper's ratio, unless --max-error or --target is given; up to 1e6, so that the "
                "threshold stays finite)",
                kDefaultRelativeError);
  command.add_option("--relative-error", arguments.relativeError, relativeHelp)
      ->check(within(kRelativeErrorRange))->excludes(maxError);
  command.add_option("--target", arguments.target, "Stop at this many samples (alone: no error threshold)")
      ->check(nonNegativeNumber());
}

SelectionRecipe resolveSelection(const SelectionArguments& selection, const ErrorArguments& errors,
                                 const StoppingArguments& stopping, const Dataset& dataset) {
  if (stopping.target == 1 || stopping.target == 2) throw InputError("--target", "a triangle needs at least 3 samples");
  if (stopping.target > dataset.sampleCount()) {
    throw InputError("--target", std::to_string(stopping.target) + " is more than the " +
                                     std::to_string(dataset.sampleCount()) + " samples of the data set");
  }
  SelectionRecipe resolved;
  resolved.errors = triangleErrorSettings(errors, dataset);
  applyErrorStride(selection, resolved.errors);
  const bool noGoal = stopping.maxError <= 0.0 && stopping.relativeError <= 0.0 && stopping.target == 0;
  const double presetMaxError = noGoal ? stopping.presetMaxError : 0.0;
  resolved.selection = selectionSettings(selection, presetMaxError > 0.0 ? presetMaxError : stopping.maxError, stopping.target);
  resolved.selection.relativeError = noGoal && presetMaxError <= 0.0 ? kDefaultRelativeError : stopping.relativeError;
  return resolved;
}

void addDecimationOptions(CLI::App& command, DecimationArguments& arguments) {
  addPresetOption(command, arguments);  // first, so that the options given beside it override it
  addStoppingOptions(command, arguments.stopping);
  addSelectionOptions(command, arguments.selection);
  addErrorOptions(command, arguments.errors, withSelectionDefaults(TriangleErrorSettings{}.synthesis));
}

SelectionRecipe resolveSelection(const DecimationArguments& arguments, const Dataset& dataset) {
  SelectionRecipe resolved = resolveSelection(arguments.selection, arguments.errors, arguments.stopping, dataset);
  resolved.preset = arguments.preset;
  return resolved;
}

}  // namespace triwalk
