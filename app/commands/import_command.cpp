// triwalk import: a capture in another tool's layout to a triwalk data set
// (core/import/dataset_import.h); README, "Bring your own capture".

#include "app/commands/commands.h"
#include "app/setup/scene_capture.h"
#include "app/setup/option_checks.h"
#include "core/import/dataset_import.h"

#include <cstdio>

namespace triwalk {

namespace {

double metresPerUnit(const std::string& units) {
  if (units == "centimetres") return 0.01;
  if (units == "millimetres") return 0.001;
  return 1.0;
}

}  // namespace

void registerImportCommand(CLI::App& app) {
  struct Arguments {
    std::string from, in, out, poses, matrix = "camera-to-world", depthKind = "euclidean", up = "z", units = "metres";
    double depthScale = 0.0;
    CaptureImportOptions options;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("import", "Make a data set of RGB-D panoramas captured or rendered elsewhere");
  command->add_option("--from", arguments->from, "Layout of the capture: realsee, pano3d or folder")
      ->required()->check(CLI::IsMember({"realsee", "pano3d", "folder"}));
  command->add_option("--in", arguments->in, "Folder of the capture")->required()->check(CLI::ExistingDirectory);
  command->add_option("--out", arguments->out, "Output data set directory")->required()->check(writableDirectory());
  command->add_option("--poses", arguments->poses, "Pose file, CSV or JSON (default: the layout's poses.csv/.json)")
      ->check(CLI::ExistingFile);
  command->add_option("--matrix", arguments->matrix, "What 4x4 pose matrices map")
      ->capture_default_str()->check(CLI::IsMember({"camera-to-world", "world-to-camera"}));
  command->add_option("--depth-scale", arguments->depthScale,
                      "Stored depth units per metre (default: the layout's; folder: 1 for .exr, 1000 for 16-bit .png)")
      ->check(positiveNumber());
  command->add_option("--depth-kind", arguments->depthKind,
                      "What depth measures: euclidean (along the ray), cube-z (z-buffer of cube faces), horizontal")
      ->capture_default_str()->check(CLI::IsMember({"euclidean", "cube-z", "horizontal"}));
  command->add_option("--up", arguments->up, "The capture's up axis")
      ->capture_default_str()->check(CLI::IsMember({"z", "y", "-y", "-z"}));
  command->add_option("--units", arguments->units, "Units of the poses' positions")
      ->capture_default_str()->check(CLI::IsMember({"metres", "centimetres", "millimetres"}));
  command->add_option("--probes-fraction", arguments->options.probesFraction,
                      "Fraction of the views held out as probes, chosen at random")
      ->capture_default_str()->check(CLI::Range(0.0, 0.9));
  command->add_option("--seed", arguments->options.seed, "Seed of the probes' choice")->capture_default_str();
  command->add_flag("--quiet", arguments->options.quiet, "No progress output");

  command->callback([arguments] {
    Arguments& a = *arguments;
    const CaptureLayout layout = parseCaptureLayout(a.from, "--from");
    LayoutOptions layoutOptions;
    layoutOptions.poses = a.poses;
    layoutOptions.matrix = parsePoseMatrix(a.matrix, "--matrix");
    if (a.depthScale > 0.0) layoutOptions.depthUnitsPerMetre = a.depthScale;
    layoutOptions.up = parseUpAxis(a.up, "--up");
    a.options.depthKind = parseDepthKind(a.depthKind, "--depth-kind");
    a.options.up = layoutOptions.up;
    a.options.metresPerUnit = metresPerUnit(a.units);

    const std::filesystem::path in = std::filesystem::absolute(a.in).lexically_normal();
    const std::vector<SourceView> views = scanCaptureLayout(layout, in, layoutOptions);
    announceReplacedDataset(a.out, "import");
    const nlohmann::json provenance = {{"layout", a.from}, {"source", in.string()}, {"matrix", a.matrix}};
    const std::string scene = (in.has_filename() ? in.filename() : in.parent_path().filename()).string();
    const CaptureImportReport report = namingOption(
        "probes_fraction", "--probes-fraction", [&] { return importCapture(views, a.options, scene, provenance, a.out); });

    std::printf("imported %d samples and %d probes of %dx%d from %s (%s layout) into %s in %.1f s\n", report.samples,
                report.probes, report.width, report.height, in.c_str(), a.from.c_str(), a.out.c_str(), report.seconds);
    std::printf("depth: %.2f%% of pixels had none (0, +inf or masked) and are +inf (no surface)", 
                100.0 * double(report.invalidDepthPixels) / double(report.pixels));
    if (!report.mostInvalidView.empty()) {
      std::printf("; most in view %s (%.1f%%)", report.mostInvalidView.c_str(), 100.0 * report.mostInvalidFraction);
    }
    std::printf("\norientation: largest tilt %.3f degrees; %d views resampled upright\n", report.largestTiltDegrees,
                report.resampledViews);
  });
}

}  // namespace triwalk
