// triwalk export: a data set in another tool's capture layout
// (core/import/dataset_export.h), the inverse of import.

#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "core/import/dataset_export.h"

#include <cstdio>

namespace triwalk {

void registerExportCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, to, out;
    bool quiet = false;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("export", "Write a data set's views in a capture layout (realsee, pano3d, folder)");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--to", arguments->to, "Layout: realsee, pano3d or folder")
      ->required()->check(CLI::IsMember({"realsee", "pano3d", "folder"}));
  command->add_option("--out", arguments->out, "Output folder (must not exist, or be empty)")
      ->required()->check(writableDirectory());
  command->add_flag("--quiet", arguments->quiet, "No progress output");
  command->callback([arguments] {
    const Dataset dataset = Dataset::open(arguments->dataset);
    const int views = exportDataset(dataset, parseCaptureLayout(arguments->to, "--to"), arguments->out, arguments->quiet);
    std::printf("exported %d views of %s in the %s layout to %s\n", views, arguments->dataset.c_str(),
                arguments->to.c_str(), arguments->out.c_str());
  });
}

}  // namespace triwalk
