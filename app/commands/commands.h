#pragma once
// Each subcommand of the triwalk binary registers itself on the CLI11 app.

#include <CLI/CLI.hpp>

namespace triwalk {

void registerCaptureCommand(CLI::App& app);
void registerExportPngCommand(CLI::App& app);
void registerRegionCommand(CLI::App& app);
void registerBenchCommand(CLI::App& app);
void registerSynthCommand(CLI::App& app);
void registerDecimateCommand(CLI::App& app);
void registerEvalCommand(CLI::App& app);
void registerRenderCommand(CLI::App& app);
void registerViewCommand(CLI::App& app);
void registerSuiteCommand(CLI::App& app);
void registerImportCommand(CLI::App& app);
void registerExportCommand(CLI::App& app);
void registerTilesCommand(CLI::App& app);

}  // namespace triwalk
