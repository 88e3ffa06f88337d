#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "app/setup/view_ids.h"
#include "core/io/dataset.h"
#include "core/io/png_io.h"
#include "core/support/errors.h"

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
  command->add_option("--out", arguments->out, "Output directory")->required()->check(writableDirectory());
  command->add_option("--max-distance", arguments->maxDistance, "Distance shown red, metres")
      ->capture_default_str()->check(positiveNumber());
  command->callback([arguments] {
    const Dataset dataset = Dataset::open(arguments->dataset);
    std::filesystem::create_directories(arguments->out);
    for (const ViewRecord* view : selectViews(dataset, arguments->views)) {
      const Panorama panorama = dataset.loadView(*view);
      const std::string stem = std::filesystem::path(view->file).stem().string();
      const std::filesystem::path colorPath = std::filesystem::path(arguments->out) / (stem + "_color.png");
      const std::filesystem::path distancePath = std::filesystem::path(arguments->out) / (stem + "_distance.png");
      writePng(colorPath, toDisplayImage(panorama.color));
      writePng(distancePath, distanceFalseColorImage(panorama.distance, arguments->maxDistance));
      std::printf("%s, %s\n", colorPath.c_str(), distancePath.c_str());
    }
  });
}

}  // namespace triwalk
