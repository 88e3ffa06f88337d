// `triwalk decimate`: edge-collapse decimation of the dense triangulation,
// written as selection.json with its collapse log.

#include "app/commands/commands.h"
#include "app/setup/decimation_options.h"
#include "app/setup/mpi_world.h"
#include "app/setup/option_checks.h"
#include "app/setup/tile_jobs.h"
#include "app/setup/walkthrough_setup.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection.h"
#include "core/selection/tiled_selection.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <cmath>
#include <cstdio>

namespace triwalk {
namespace {

std::string tilesHelp() {
  return "Decimate in tiles, stitched (docs/DESIGN.md, \"Tiled selection\"): a number of tiles, off, or auto (above " +
         std::to_string(kTileSamples) + " samples, tiles of at most " + std::to_string(kTileSamples) +
         " with their margins; at 1,940 samples the tiles took a ninth of one decimation's time, their probe error "
         "+0.3% +- 0.9% against it at the default threshold and +0.7% +- 1.1% at --target 256; docs/RESULTS.md)";
}

// The tiled decimation: its work folder beside the selection file, kept
// until the selection is written, so a stopped run goes on from its tiles.
void decimateTiled(const Dataset& dataset, const SelectionRecipe& resolved, int tiles, int jobs,
                   const std::string& out, bool quiet) {
  const bool worker = rankFromEnvironment() != 0;  // an MPI rank other than 0 only runs tiles
  if (!worker) std::printf("%s; in tiles\n", describeErrorSettings(resolved.errors).c_str());
  InterruptScope interruptScope;
  const std::filesystem::path folder = std::filesystem::path(out).concat(".tiles");
  TilePlanRequest request{describeSelectionRecipe(resolved), tiles, jobs};
  std::optional<StitchResult> stitched = decimateInTiles(dataset, request, folder, quiet || worker);
  if (!stitched) return;
  writeSelection(out, stitched->selection, dataset);
  std::filesystem::remove_all(folder);
  std::printf("kept %zu of %d samples, %zu triangles: the %zu tiles' cores kept %zu, %s\n",
              stitched->selection.samples.size(), dataset.sampleCount(), stitched->selection.triangles.size(),
              stitched->tiles, stitched->unionSamples, describeSeamPass(*stitched).c_str());
  if (const std::string outside = describeSamplesOutsideTriangles(dataset, selectionMesh(stitched->selection, dataset));
      !outside.empty()) {
    std::printf("%s\n", outside.c_str());
  }
  std::printf("wrote %s\n", out.c_str());
}

}  // namespace

void registerDecimateCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, out;
    std::string tiles = "auto";
    int jobs = defaultJobs();
    bool quiet = false;
    DecimationArguments decimation;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("decimate", "Select reference samples by edge-collapse decimation");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--out", arguments->out, "Selection file to write (selection.json)")->required()->check(writableFile(OutputKind::Selection));
  command->add_option("--tiles", arguments->tiles, tilesHelp())->capture_default_str()->check(tileCount());
  command->add_option("--jobs", arguments->jobs,
                      "Tiles decimated at once on this machine (default: the cores); under mpirun, one per rank")
      ->check(CLI::Range(1, 4096));
  command->add_flag("--quiet", arguments->quiet, "No progress output");
  addDecimationOptions(*command, arguments->decimation);

  command->callback([arguments] {
    const Arguments& a = *arguments;
    const Dataset dataset = Dataset::open(a.dataset);
    const SelectionRecipe resolved = resolveSelection(a.decimation, dataset);
    const int tiles = tileCountFor(a.tiles, dataset.sampleCount());
    if (tiles != 1) {
      decimateTiled(dataset, resolved, tiles, a.jobs, a.out, a.quiet);
      return;
    }
    TriangleErrorSettings settings = resolved.errors;
    std::printf("%s\n", describeErrorSettings(settings).c_str());

    InterruptScope interruptScope;
    DatasetTriangleErrors errors(dataset, settings, LoadedViews::Samples, a.quiet);
    SelectionRun run = selectReferences(dataset, errors, resolved.selection, a.quiet);
    if (resolved.selection.relativeError > 0.0) {
      std::printf("error threshold: %.2f x the dense triangulation's mean triangle error %.4f = %.4f\n",
                  resolved.selection.relativeError, run.denseMeanError, run.maxError);
    }
    SelectionRecipe made = resolved;  // with the absolute threshold a relative one meant
    made.selection.decimation.maxError = run.maxError;
    run.selection.settings = describeSelectionRecipe(made);
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
