// `triwalk decimate`: edge-collapse decimation of the dense triangulation,
// written as selection.json with its collapse log.

#include "app/commands/commands.h"
#include "app/setup/decimation_options.h"
#include "app/setup/option_checks.h"
#include "app/setup/walkthrough_setup.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <cmath>
#include <cstdio>

namespace triwalk {

void registerDecimateCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, out;
    double maxError = 0.0, relativeError = 0.0;
    int target = 0;
    bool quiet = false;
    SelectionArguments selection;
    ErrorArguments errors;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("decimate", "Select reference samples by edge-collapse decimation");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--out", arguments->out, "Selection file to write (selection.json)")->required()->check(writableFile());
  CLI::Option* maxError = command->add_option(
      "--max-error", arguments->maxError,
      "Stop before a collapse whose error exceeds this absolute value (the paper's 1.85; up to 1e9, above any error, "
      "which the selection file can hold)")
      ->check(within(kMaxErrorRange));
  char relativeHelp[400];
  std::snprintf(relativeHelp, sizeof relativeHelp,
                "Stop before a collapse whose error exceeds this many times the dense triangulation's mean triangle error "
                "(default %.2f, the paper's ratio, unless --max-error or --target is given; up to 1e6, so that the "
                "threshold stays finite)",
                kDefaultRelativeError);
  command->add_option("--relative-error", arguments->relativeError, relativeHelp)
      ->check(within(kRelativeErrorRange))->excludes(maxError);
  command->add_option("--target", arguments->target, "Stop at this many samples (alone: no error threshold)")
      ->check(nonNegativeNumber());
  addSelectionOptions(*command, arguments->selection);
  command->add_flag("--quiet", arguments->quiet, "No progress output");
  addErrorOptions(*command, arguments->errors, withSelectionDefaults(TriangleErrorSettings{}.synthesis));

  command->callback([arguments] {
    const Arguments& a = *arguments;
    if (a.target == 1 || a.target == 2) throw InputError("--target", "a triangle needs at least 3 samples");
    const Dataset dataset = Dataset::open(a.dataset);
    if (a.target > dataset.sampleCount()) {
      throw InputError("--target", std::to_string(a.target) + " is more than the " + std::to_string(dataset.sampleCount()) +
                                       " samples of the data set");
    }
    TriangleErrorSettings settings = triangleErrorSettings(a.errors, dataset);
    applyErrorStride(a.selection, settings);
    std::printf("%s\n", describeErrorSettings(settings).c_str());

    InterruptScope interruptScope;
    DatasetTriangleErrors errors(dataset, settings, LoadedViews::Samples, a.quiet);
    SelectionSettings selection = selectionSettings(a.selection, a.maxError, a.target);
    const bool noGoal = a.maxError <= 0.0 && a.relativeError <= 0.0 && a.target == 0;
    selection.relativeError = noGoal ? kDefaultRelativeError : a.relativeError;
    SelectionRun run = selectReferences(dataset, errors, selection, a.quiet);
    if (selection.relativeError > 0.0) {
      std::printf("error threshold: %.2f x the dense triangulation's mean triangle error %.4f = %.4f\n",
                  selection.relativeError, run.denseMeanError, run.maxError);
    }
    selection.decimation.maxError = run.maxError;

    run.selection.settings = describeSelectionSettings(selection, settings);
    writeSelection(a.out, run.selection, dataset);

    const DecimationStatistics& statistics = run.statistics;
    std::printf("kept %zu of %d samples, %zu triangles; stopped: %s", run.selection.samples.size(), run.initialSamples,
                run.selection.triangles.size(), stopReasonName(run.stopReason));
    if (std::isfinite(run.selection.nextCost)) {
      std::printf(run.stopReason == StopReason::MaxError ? " (lowest error of a refused collapse %.3f)" : " (next cost %.3f)",
                  run.selection.nextCost);
    }
    std::printf("\n");
    if (const std::string outside = describeSamplesOutsideTriangles(dataset, selectionMesh(run.selection, dataset));
        !outside.empty()) {
      std::printf("%s\n", outside.c_str());
    }
    std::printf(
        "%zu collapses in %.1f s (edge costing %.1f s); errors computed %llu, served from the cache %llu; "
        "stale heap entries skipped %llu\n",
        run.collapses, run.collapseSeconds, run.costingSeconds, (unsigned long long)statistics.errorsComputed,
        (unsigned long long)statistics.cacheHits, (unsigned long long)statistics.staleEntriesSkipped);
    if (statistics.straightStretchSearches > 0) {
      std::printf("%llu of them took a reference off a straight stretch of the boundary, where no other was valid\n",
                  (unsigned long long)statistics.straightStretchSearches);
    }
    if (statistics.removals > 0) {
      std::printf(
          "%llu of them removed a reference with its triangles, where no collapse was valid (a loop cut open)\n",
          (unsigned long long)statistics.removals);
    }
    const RefinementResult& refinement = run.refinement;
    if (refinement.radius > 0.0) {
      std::printf(
          "refinement: %zu moves (%d exchanges, %d passes of local moves within %.2f m); mean error over the "
          "dense samples %.4f -> %.4f; %.1f s, errors computed %llu (%llu by the exchange searches), served from the "
          "cache %llu\n",
          refinement.moves.size(), refinement.exchanges, refinement.passes, refinement.radius,
          refinement.objectiveBefore, refinement.objectiveAfter, run.refinementSeconds,
          (unsigned long long)refinement.errorsComputed, (unsigned long long)refinement.exchangeSearchErrors,
          (unsigned long long)refinement.cacheHits);
    }
    std::printf("warped layers computed %llu, reused %llu\n", (unsigned long long)errors.layerCache().misses(),
                (unsigned long long)errors.layerCache().hits());
    const ViewLoads& loads = errors.loads();
    if (loads.panoramasRead + loads.panoramasDownsampled == 0) {
      std::printf("views at %dx%d: read from their EXR files (the data set's width)", settings.width, settings.width / 2);
    } else {
      std::printf("views at %dx%d: %d read from the data set's store, %d downsampled from their EXR files",
                  settings.width, settings.width / 2, loads.panoramasRead, loads.panoramasDownsampled);
    }
    std::printf("; simplified meshes: %d read, %d simplified\n", loads.meshesRead, loads.meshesSimplified);
    std::printf("wrote %s\n", a.out.c_str());
  });
}

}  // namespace triwalk
