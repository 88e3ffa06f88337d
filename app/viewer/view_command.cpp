// `triwalk view`: open the walkthrough viewer.

#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "app/setup/quality_options.h"
#include "app/setup/walkthrough_setup.h"
#include "app/viewer/viewer_app.h"
#include "app/viewer/viewer_controls.h"
#include "core/io/camera_path_file.h"
#include "core/selection/triangle_error.h"
#include "core/support/errors.h"

namespace triwalk {

void registerViewCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, selection, size = "1280x720", screenshot, path, record, sidebar = "remembered", overlay = "none";
    bool hideUi = false;
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
  command->add_option("--frames", arguments->frames,
                      "Render this many frames (each 1/30 s of --path's playback), then wait for the panoramas the "
                      "last one shows and the decimation's (at most 300 s, said if it gives up), write --screenshot "
                      "and exit: the same arguments give the same screenshot")
      ->check(CLI::PositiveNumber);
  command->add_option("--screenshot", arguments->screenshot, "With --frames: PNG of the window at the last frame")->check(writableFile(OutputKind::Png));
  command->add_option("--path", arguments->path,
                      "Camera path to play at start, in real time and smoothly: a walk recorded here (R) at its own "
                      "speed, a path of one pose a frame at 30 poses a second (render --path reads the same files)");
  command->add_option("--record", arguments->record,
                      "Record the walk from the start (R ends it) into this camera path file, also when the viewer "
                      "closes")
      ->check(writableFile(OutputKind::CameraPath));
  command->add_option("--overlay", arguments->overlay,
                      "Colour the view at start by: trust (how many references agree on each pixel, and how well they "
                      "saw it), error (standing near a captured sample or held-out probe, the per-pixel error against its "
                      "panorama), or "
                      "none (T and E switch them)")
      ->capture_default_str()->check(CLI::IsMember({"none", "trust", "error"}));
  command->add_flag("--hide-ui", arguments->hideUi, "The view alone: no tools, hints or notices (screenshots, videos of the window)");
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
    if (!a.path.empty()) options.path = readCameraPath(a.path), options.pathFile = a.path;
    options.record = a.record;
    options.hideUi = a.hideUi;
    options.overlay = a.overlay == "trust" ? ViewOverlay::Trust : a.overlay == "error" ? ViewOverlay::Error : ViewOverlay::None;
    if (a.hideUi && a.sidebar == "shown") throw InputError("--hide-ui", "shows no tools: leave out --sidebar shown");
    if (options.frames > 0 && options.screenshot.empty()) throw InputError("--frames", "give --screenshot FILE too");
    runViewer(options);
  });
}

}  // namespace triwalk
