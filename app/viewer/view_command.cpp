// `triwalk view`: open the walkthrough viewer.

#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "app/setup/quality_options.h"
#include "app/setup/walkthrough_setup.h"
#include "app/viewer/viewer_app.h"
#include "app/viewer/viewer_controls.h"
#include "core/selection/triangle_error.h"
#include "core/support/errors.h"

namespace triwalk {

void registerViewCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, selection, size = "1280x720", screenshot, path, sidebar = "remembered";
    int frames = 0;
    int errorWidth = 0, errorStride = 0;
    size_t cacheMegabytes = 1024;
    QualityArguments quality;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("view", "Walk through a data set (GLFW window with Dear ImGui panels)");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--selection", arguments->selection,
                      "Selection to walk through and step (default: the dense triangulation, to decimate here)");
  command->add_option("--size", arguments->size, "Window size WIDTHxHEIGHT")->capture_default_str();
  command->add_option("--cache-mb", arguments->cacheMegabytes, "Memory for resident panoramas, MiB")->capture_default_str();
  command->add_option("--error-width", arguments->errorWidth, "Panorama width of the decimation's errors (default: the "
                      "selection's, else the largest width not above " + std::to_string(kDefaultErrorWidth) +
                      " that divides the data set's)")
      ->check(nonNegativeNumber());
  command->add_option("--error-stride", arguments->errorStride, "Compute the decimation's errors on every N-th row and "
                      "column of the error panorama, as decimate's --error-stride (2: about 2.6x the collapses a "
                      "second, at a measured cost in quality: docs/history/RESULTS-2026-11.md); default: the selection's, else 1")
      ->check(errorStride());
  command->add_option("--sidebar", arguments->sidebar,
                      "The tools sidebar at start: shown, hidden, or as you left it (Tab switches; kept in "
                      "$XDG_CONFIG_HOME/triwalk/viewer.json)")
      ->capture_default_str()->check(CLI::IsMember({"shown", "hidden", "remembered"}));
  command->footer(describeViewerControls());
  command->add_option("--frames", arguments->frames, "Render this many frames, write --screenshot and exit");
  command->add_option("--screenshot", arguments->screenshot, "With --frames: PNG of the window at the last frame")->check(writableFile());
  command->add_option("--path", arguments->path, "With --frames: camera path file (x y z yaw pitch a line)");
  // Simplified meshes: a walk fits the frame budget at a higher resolution
  // (docs/history/BENCHMARKS-2026-11.md, "stored simplified meshes, and the scaling row");
  // render keeps the grid.
  addRenderQualityOptions(*command, arguments->quality, SourceMesh::Simplified);
  command->callback([arguments] {
    const Arguments& a = *arguments;
    ViewerOptions options;
    options.dataset = a.dataset;
    options.selection = a.selection;
    parseSize(a.size, "--size", options.width, options.height);
    options.cacheBytes = a.cacheMegabytes << 20;
    options.errorWidth = a.errorWidth;
    options.errorStride = a.errorStride;
    options.synthesis = synthesisOptions(a.quality);
    if (a.sidebar != "remembered") options.sidebar = a.sidebar == "shown";
    options.frames = a.frames;
    options.screenshot = a.screenshot;
    if (!a.path.empty()) options.path = readCameraPath(a.path);
    if (options.frames > 0 && options.screenshot.empty()) throw InputError("--frames", "give --screenshot FILE too");
    runViewer(options);
  });
}

}  // namespace triwalk
