#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "app/setup/view_ids.h"
#include "core/io/dataset.h"
#include "core/image/image_annotation.h"
#include "core/io/atomic_file.h"
#include "core/io/png_io.h"
#include "core/io/staged_directory.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <cmath>
#include <cstdio>

namespace triwalk {

namespace {

std::vector<const ViewRecord*> selectViews(const Dataset& dataset, const std::vector<std::string>& names) {
  std::vector<const ViewRecord*> views;
  for (const std::string& name : names) {
    if (name == "all") {
      for (const ViewRecord& view : dataset.manifest().samples) views.push_back(&view);
      for (const ViewRecord& view : dataset.manifest().probes) views.push_back(&view);
    } else {
      views.push_back(&findView(dataset, name, "--views"));
    }
  }
  return views;
}

// Marks a folder export-png made, so that the next run may replace it.
constexpr const char* kExportPngMarker = ".triwalk-export-png";

}  // namespace

void registerExportPngCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, out;
    std::vector<std::string> views{"0"};
    float maxDistance = 20.0f;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("export-png", "Write color and false-color distance PNGs of views");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--views", arguments->views, "Views: sample ids, pN for probes, or all")
      ->delimiter(',')->capture_default_str();
  command->add_option("--out", arguments->out,
                      "Output directory, replaced as a whole (an existing one must be empty or hold an earlier "
                      "export-png)")
      ->required()->check(writableDirectory());
  command->add_option("--max-distance", arguments->maxDistance, "Distance shown red, metres")
      ->capture_default_str()->check(positiveNumber());
  command->callback([arguments] {
    const Dataset dataset = Dataset::open(arguments->dataset);
    const std::vector<const ViewRecord*> views = selectViews(dataset, arguments->views);
    // Written beside --out and moved into place whole; an earlier
    // export-png's folder (it holds the marker) is replaced.
    StagedDirectory staging(arguments->out, kExportPngMarker, "an earlier export-png");
    staging.writeFile(kExportPngMarker, [](const std::filesystem::path& path) {
      writeTextFileAtomically(path, "written by triwalk export-png\n");
    });
    std::vector<std::string> written;
    InterruptScope interruptScope;
    for (const ViewRecord* view : views) {
      throwIfInterrupted();
      const Panorama panorama = dataset.loadView(*view);
      const std::string stem = std::filesystem::path(view->file).stem().string();
      staging.writeFile(stem + "_color.png",
                        [&](const std::filesystem::path& path) { writePng(path, toDisplayImage(panorama.color)); });
      staging.writeFile(stem + "_distance.png", [&](const std::filesystem::path& path) {
        writePng(path, withColourBar(distanceFalseColorImage(panorama.distance, arguments->maxDistance),
                                     arguments->maxDistance, "distance in metres, log scale from 0.1 m; black: sky"));
      });
      written.push_back(stem);
    }
    staging.commit();
    const std::filesystem::path out(arguments->out);
    for (const std::string& stem : written) {
      std::printf("%s, %s\n", (out / (stem + "_color.png")).c_str(), (out / (stem + "_distance.png")).c_str());
    }
  });
}

}  // namespace triwalk
