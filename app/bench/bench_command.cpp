// `triwalk bench`: every performance figure the project quotes comes from
// here, printed with the machine and the data size.

#include "app/bench/bench_groups.h"
#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "app/setup/scene_loading.h"
#include "app/setup/tile_jobs.h"
#include "core/support/errors.h"
#include "render/gl/gl_context.h"
#include "scene/scene_description.h"

#include <cstdio>
#include <set>

namespace triwalk {

void registerBenchCommand(CLI::App& app) {
  struct Arguments {
    std::vector<std::string> only;
    std::string gl = "auto";
    int captureViews = 20;
    BenchSelectionErrors decimationErrors;
    std::string dataset, selection;
    std::string regionScene = "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc";
    SceneImportArguments regionImport;
    std::vector<std::string> tileFloors = {"5x2", "10x4"};
    int jobs = defaultJobs();
    bool tilesAgainstWhole = false;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("bench", "Measure throughput and print a table (machine, sizes, figures)");
  command
      ->add_option("--only", arguments->only,
                   "Run only these groups: capture, region, decimate, scaling, tiles, warp, render, viewer (scaling and tiles: not in "
                   "the default run)")
      ->delimiter(',')
      ->check(CLI::IsMember({"capture", "region", "decimate", "scaling", "tiles", "warp", "render", "viewer"}));
  command->add_option("--tile-floors", arguments->tileFloors,
                      "Generated floors (builtin-floor sizes) the tiles figure decimates, smallest first")
      ->delimiter(',')->capture_default_str();
  command->add_option("--jobs", arguments->jobs, "Tile processes at once in the tiles figure (default: the cores)")
      ->check(CLI::Range(1, 4096));
  command->add_flag("--tiles-against-whole", arguments->tilesAgainstWhole,
                    "The tiles figure also decimates its first floor whole (--tiles off): the time tiling saves");
  command->add_option("--gl", arguments->gl, "Headless OpenGL: auto, egl or osmesa")->capture_default_str();
  // The end-to-end figure captures views / 4 paths of 4, and a capture needs at least 2 paths.
  command
      ->add_option("--capture-views", arguments->captureViews,
                   "Panoramas rendered for the capture figure (at least 8: the end-to-end figure captures paths of 4)")
      ->capture_default_str()
      ->check(CLI::Range(8, 100000));
  command->add_option("--decimation-width", arguments->decimationErrors.width, "Panorama width decimation works at")
      ->capture_default_str()
      ->check(CLI::IsMember({64, 128, 256, 512, 1024}));
  command
      ->add_option("--decimation-error-stride", arguments->decimationErrors.stride,
                   "The decimation's errors on every N-th row and column (decimate's --error-stride)")
      ->capture_default_str()
      ->check(errorStride());
  command->add_option("--dataset", arguments->dataset,
                      "Data set for the decimation figures (default: capture the default one first)");
  command->add_option("--selection", arguments->selection, "Selection for the viewer figure (default: all samples)");
  command
      ->add_option("--region-scene", arguments->regionScene, "Scene whose walkable region the region figure searches")
      ->capture_default_str();
  addSceneImportOptions(*command, arguments->regionImport);
  command->callback([arguments] {
    const std::set<std::string> only(arguments->only.begin(), arguments->only.end());
    auto selected = [&](const std::string& group) { return only.empty() || only.count(group) > 0; };
    BenchTable table;
    std::string glDescription;
    auto context = createHeadlessContext(parseHeadlessBackend(arguments->gl));
    glDescription = context->description();
    if (selected("capture")) {
      const BenchViews views = captureBenchViews();
      benchCapture(table, views.scene, 1024, arguments->captureViews);
    }
    if (selected("region")) benchRegion(table, arguments->regionScene, arguments->regionImport);
    if (selected("decimate")) {
      benchDecimate(table, loadSceneDescription(builtinScenePath()), arguments->dataset, arguments->decimationErrors);
    }
    // Two captures and decimations, about half an hour here: only when asked.
    if (only.count("scaling")) {
      benchScaling(table, loadSceneDescription(builtinScenePath()), arguments->decimationErrors);
    }
    // Captures of floors and their tiled decimations, most of an hour here:
    // only when asked.
    if (only.count("tiles")) {
      benchTiles(table, arguments->tileFloors, arguments->decimationErrors.width, arguments->jobs,
                 arguments->tilesAgainstWhole);
    }
    if (selected("warp") || selected("render")) {
      const BenchViews views = captureBenchViews();
      if (selected("warp")) benchWarp(table, views, arguments->decimationErrors.width);
      if (selected("render")) benchRender(table, views, 60);
    }
    if (selected("viewer")) {
      if (arguments->dataset.empty()) {
        throw InputError("--dataset", "the viewer figure walks through a data set: give --dataset");
      }
      const Dataset dataset = Dataset::open(arguments->dataset);
      benchViewer(table, dataset, arguments->selection, 300);
    }
    table.print(glDescription);
  });
}

}  // namespace triwalk
