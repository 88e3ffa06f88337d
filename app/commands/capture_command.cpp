// `triwalk capture`: render a scene's dense samples and probes into a data set.

#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "app/setup/scene_capture.h"
#include "core/io/exr_io.h"
#include "core/io/json_fields.h"

namespace triwalk {

void registerCaptureCommand(CLI::App& app) {
  struct Arguments {
    std::string scene = "builtin";
    std::string out;
    std::string gl = "auto";
    std::vector<float> area;
    std::string region;
    std::vector<float> start;
    float eyeHeight = 0.0f;
    float spacing = 0.0f;
    bool autoArea = false;
    CaptureOptions options;
    SceneImportArguments import;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("capture", "Render the dense panorama samples and held-out probes of a scene");
  command->add_option("--scene", arguments->scene,
                      "builtin, builtin-floor:CxR[:SEED] (a generated floor of C x R rooms with corridors, captured "
                      "3 samples a metre apart), a scene description (.json) or any file Assimp reads")
      ->capture_default_str();
  command->add_option("--out", arguments->out, "Output data set directory")->required()->check(writableDirectory());
  command->add_option("--paths", arguments->options.paths, "Number of parallel capture paths")
      ->capture_default_str()->check(CLI::Range(1, int(kMaxViews)));
  command->add_option("--per-path", arguments->options.perPath, "Samples per path")
      ->capture_default_str()->check(CLI::Range(1, int(kMaxViews)));
  command->add_option("--spacing", arguments->spacing,
                      "Metres between samples and between paths (overrides --paths and --per-path)")
      ->check(positiveNumber());
  command->add_option("--area", arguments->area, "Sampled rectangle x0,y0,x1,y1 in metres (default: the scene's)")
      ->delimiter(',')->expected(4)->check(coordinate());
  command->add_option("--region", arguments->region,
                      "Walkable region file: {\"polygons\": [{\"outer\": [[x, y], ...], \"holes\": [...]}, ...]} in metres")
      ->check(CLI::ExistingFile)
      ->excludes("--area");
  command->add_option("--start", arguments->start,
                      "X,Y in metres: where the automatic region's flood fill starts (default: spawn points, else the "
                      "scene's centre)")
      ->delimiter(',')->expected(2)->check(coordinate())->excludes("--area")->excludes("--region");
  command->add_option("--eye-height", arguments->eyeHeight, "Camera height above the floor, metres (default: the scene's)")
      ->check(positiveNumber())->check(coordinate());
  command->add_option("--width", arguments->options.width,
                      "Panorama width in pixels, even (height = width / 2); at most " + std::to_string(kMaxPanoramaWidth) +
                          ", the widest a data set's views may be")
      ->capture_default_str()->check(CLI::Range(16, kMaxPanoramaWidth));
  command->add_option("--face-size", arguments->options.faceSize,
                      "Cube face resolution (0: 3/8 of the width); at most the OpenGL renderbuffer size")
      ->capture_default_str()->check(CLI::Range(0, kMaxPanoramaWidth));
  command->add_option("--probes", arguments->options.probes, "Held-out views at random positions")
      ->capture_default_str()->check(CLI::Range(0, int(kMaxViews)));
  command->add_option("--seed", arguments->options.seed, "Seed of the probe positions")->capture_default_str();
  command->add_flag("--closed-doors", arguments->options.closedDoors,
                    "Draw door leaves (IFC door elements) in the captures (default: doors open, as the walkable "
                    "region passes through them)");
  command->add_flag("--auto-area", arguments->autoArea,
                    "Find the walkable region by a flood fill of probes (default for imported scenes without --area "
                    "or --region)");
  command->add_option("--gl", arguments->gl, "Headless OpenGL: auto, egl or osmesa")->capture_default_str();
  command->add_flag("--quiet", arguments->options.quiet, "No progress output");
  addSceneImportOptions(*command, arguments->import);

  command->callback([arguments, command] {
    Arguments& a = *arguments;
    SceneCaptureRequest request;
    request.scene = a.scene;
    request.import = a.import;
    request.options = a.options;
    if (!a.area.empty()) request.options.area = glm::vec4(a.area[0], a.area[1], a.area[2], a.area[3]);
    if (!a.region.empty()) request.options.region = WalkableRegion::fromJson(readJsonFile(a.region), a.region);
    if (!a.start.empty()) request.starts.push_back({a.start[0], a.start[1]});
    if (a.eyeHeight > 0.0f) request.options.eyeHeight = a.eyeHeight;
    if (a.spacing > 0.0f) request.options.spacing = a.spacing;
    request.autoArea = a.autoArea;
    request.densityGiven = command->count("--spacing") + command->count("--paths") + command->count("--per-path") > 0;
    request.gl = a.gl;
    request.out = a.out;
    captureScene(request);
  });
}

}  // namespace triwalk
