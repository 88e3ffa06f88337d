// `triwalk tiles plan|run|stitch`: a tiled decimation as separate jobs, for
// a batch scheduler (a Slurm job array runs one tile per task). decimate
// runs the same three steps by itself, on one machine or under mpirun.

#include "app/commands/commands.h"
#include "app/setup/decimation_options.h"
#include "app/setup/option_checks.h"
#include "app/setup/tile_jobs.h"
#include "app/setup/walkthrough_setup.h"
#include "core/io/output_lock.h"
#include "core/selection/tile_files.h"
#include "core/selection/tiled_selection.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <cstdio>

namespace triwalk {
namespace {

void registerPlan(CLI::App& tiles) {
  struct Arguments {
    std::string dataset, out, tiles = "auto";
    int jobs = defaultJobs();
    bool quiet = false;
    DecimationArguments decimation;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = tiles.add_subcommand(
      "plan", "Cut a data set into tiles and write the plan every tile runs with (measuring the dense error first)");
  command->add_option("--dataset", arguments->dataset, "Data set directory (on a file system every job reads)")->required();
  command->add_option("--out", arguments->out, "Work folder for the plan and the tiles' outcomes")
      ->required()->check(writableDirectory());
  command->add_option("--tiles", arguments->tiles,
                      "Number of tiles, or auto (tiles of at most " + std::to_string(kTileSamples) +
                          " samples with their margins)")
      ->capture_default_str()->check(tileCount());
  command->add_option("--jobs", arguments->jobs, "Tiles measured at once (default: the cores)")->check(CLI::Range(1, 4096));
  command->add_flag("--quiet", arguments->quiet, "No progress output");
  addDecimationOptions(*command, arguments->decimation);
  command->callback([arguments] {
    const Arguments& a = *arguments;
    const Dataset dataset = Dataset::open(a.dataset);
    const SelectionRecipe resolved = resolveSelection(a.decimation, dataset);
    // auto: tiles within kTileSamples whatever the capture's size (decimate's
    // auto also decides whether to tile at all).
    const int count = a.tiles == "auto" ? 0 : tileCountFor(a.tiles, dataset.sampleCount());
    InterruptScope interruptScope;
    const OutputLock lock(a.out);
    const TilePlanRequest request{describeSelectionRecipe(resolved), count, a.jobs};
    writeTilePlan(a.out, planTiles(dataset, request, a.quiet), dataset);
    const TilePlan plan = readTilePlan(a.out, dataset);
    std::printf("planned %zu tiles of %d samples (margin %.2f m, seam band %.2f m)", plan.tiles.size(),
                dataset.sampleCount(), plan.margin, plan.band);
    if (plan.denseMeanError > 0.0) {
      std::printf("; error threshold %.4f (%.2f x the dense mean %.4f)", plan.settings.value("max_error", 0.0),
                  plan.settings.value("relative_error", 0.0), plan.denseMeanError);
    }
    std::printf("\nrun tiles 0 to %zu: triwalk tiles run --plan %s --tile K\n", plan.tiles.size() - 1, a.out.c_str());
  });
}

void registerRun(CLI::App& tiles) {
  struct Arguments {
    std::string plan;
    int tile = -1;
    bool quiet = false;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = tiles.add_subcommand("run", "Decimate one tile of a plan (a job array's task)");
  command->add_option("--plan", arguments->plan, "Work folder of tiles plan")->required();
  command->add_option("--tile", arguments->tile, "The tile, from 0 (e.g. $SLURM_ARRAY_TASK_ID)")
      ->required()->check(nonNegativeNumber());
  command->add_flag("--quiet", arguments->quiet, "No progress output");
  command->callback([arguments] {
    const Arguments& a = *arguments;
    const Dataset dataset = Dataset::open(tilePlanDataset(a.plan));
    const TilePlan plan = readTilePlan(a.plan, dataset);
    if (a.tile >= int(plan.tiles.size())) {
      throw InputError("--tile", std::to_string(a.tile) + " is not a tile of " + a.plan + " (0 to " +
                                     std::to_string(plan.tiles.size() - 1) + ")");
    }
    InterruptScope interruptScope;
    const TileOutcome outcome = runTile(dataset, plan, a.tile, tileLayerCacheBytes(1), a.quiet);
    writeTileOutcome(a.plan, plan, a.tile, outcome, dataset);
    std::printf("tile %d of %zu: %zu samples, kept %zu references of its core in %.1f s; wrote %s\n", a.tile,
                plan.tiles.size(), plan.tiles[size_t(a.tile)].samples.size(), outcome.references.size(), outcome.seconds,
                tileOutcomeFile(a.plan, a.tile).c_str());
  });
}

void registerStitch(CLI::App& tiles) {
  struct Arguments {
    std::string plan, out;
    int jobs = defaultJobs();
    bool quiet = false;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = tiles.add_subcommand("stitch", "Stitch the tiles of a plan into one selection file");
  command->add_option("--plan", arguments->plan, "Work folder of tiles plan")->required();
  command->add_option("--out", arguments->out, "Selection file to write (selection.json)")->required()->check(writableFile(OutputKind::Selection));
  command->add_option("--jobs", arguments->jobs, "Seam steps run at once (default: the cores; the selection is the same)")
      ->check(CLI::Range(1, 4096));
  command->add_flag("--quiet", arguments->quiet, "No progress output");
  command->callback([arguments] {
    const Arguments& a = *arguments;
    const Dataset dataset = Dataset::open(tilePlanDataset(a.plan));
    const TilePlan plan = readTilePlan(a.plan, dataset);
    const std::vector<TileOutcome> outcomes = readTileOutcomes(a.plan, plan, dataset);
    InterruptScope interruptScope;
    StitchResult stitched = stitchTiles(dataset, plan, outcomes, a.jobs, a.quiet);
    writeSelection(a.out, stitched.selection, dataset);
    std::printf("kept %zu of %d samples (the cores kept %zu; %s); wrote %s\n", stitched.selection.samples.size(),
                dataset.sampleCount(), stitched.unionSamples, describeSeamPass(stitched).c_str(), a.out.c_str());
  });
}

}  // namespace

void registerTilesCommand(CLI::App& app) {
  CLI::App* tiles = app.add_subcommand(
      "tiles", "A tiled decimation as separate jobs for a batch scheduler: plan, run each tile, stitch");
  tiles->require_subcommand(1);
  registerPlan(*tiles);
  registerRun(*tiles);
  registerStitch(*tiles);
}

}  // namespace triwalk
