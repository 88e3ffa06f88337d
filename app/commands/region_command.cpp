// `triwalk region`: a top-view PNG of a data set's walkable region, its
// samples and probes, and the view triangles of a selection (the dense
// triangulation when none is given).

#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "app/setup/top_view_image.h"
#include "app/setup/walkthrough_setup.h"
#include "core/io/png_io.h"

#include <cstdio>

namespace triwalk {

void registerRegionCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, selection, out;
    int size = 1024;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("region", "Write a top view of the walkable region, samples, probes and view triangles");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--selection", arguments->selection, "selection.json whose triangles to draw (default: the dense ones)")
      ->check(CLI::ExistingFile);
  command->add_option("--out", arguments->out, "Output PNG")->required()->check(writableFile(OutputKind::Png));
  command->add_option("--size", arguments->size, "Pixels along the longer side")->capture_default_str()->check(CLI::Range(64, 8192));
  command->callback([arguments] {
    const Arguments& a = *arguments;
    const Dataset dataset = Dataset::open(a.dataset);
    const ViewMesh mesh = walkthroughMesh(dataset, a.selection);
    const WalkableRegion region = dataset.walkableRegion();
    writePng(a.out, topViewImage(dataset, mesh, a.size));
    std::printf("%s: region %.1f m2 in %zu part%s, %d samples, %d probes, %d view triangles over %d references\n",
                a.out.c_str(), region.area(), region.polygons().size(), region.polygons().size() == 1 ? "" : "s",
                dataset.sampleCount(), dataset.probeCount(), mesh.triangleCount(), mesh.vertexCount());
    if (const std::string outside = describeSamplesOutsideTriangles(dataset, mesh); !outside.empty()) {
      std::printf("%s\n", outside.c_str());
    }
  });
}

}  // namespace triwalk
