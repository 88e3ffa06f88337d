#include "app/setup/quality_options.h"

#include "app/setup/option_checks.h"

#include <cstdio>

namespace triwalk {

namespace {

void addStretchOptions(CLI::App& command, QualityArguments& arguments) {
  command.add_option("--stretch-test", arguments.stretchTest, "Rubber-sheet test: grazing-angle, depth-ratio or none")
      ->capture_default_str()->group("Warp");
  command.add_option("--grazing-angle", arguments.grazingAngleDegrees,
                     "grazing-angle: drop triangles seen at less than this angle, degrees")
      ->capture_default_str()->check(within(kGrazingAngleRange))->group("Warp");
  command.add_option("--depth-ratio", arguments.maxDepthRatio, "depth-ratio: drop triangles with farthest/nearest above this")
      ->capture_default_str()->check(within(kDepthRatioRange))->group("Warp");
}

void addSourceMeshOptions(CLI::App& command, QualityArguments& arguments) {
  command.add_option("--source-mesh", arguments.sourceMesh,
                     "Triangles each reference warps: simplified (its grid simplified within --mesh-tolerance, colours "
                     "looked up along each ray) or grid (two per pixel quad, the exact reference)")
      ->capture_default_str()->check(CLI::IsMember({"simplified", "grid"}))->group("Warp");
  command.add_option("--mesh-tolerance", arguments.meshTolerancePixels,
                     "simplified: how far the surface may move, in reference pixels (at the distance nearer than which "
                     "5% of the reference's surface lies)")
      ->capture_default_str()->check(within(kMeshToleranceRange))->group("Warp");
}

void addHoleOption(CLI::App& command, QualityArguments& arguments, HoleMode holes, const char* help) {
  arguments.holes = holeModeName(holes);
  command.add_option("--holes", arguments.holes, help)
      ->capture_default_str()->check(CLI::IsMember({"fill", "mark", "black"}))->group("Blend");
}

void addBlendOptions(CLI::App& command, QualityArguments& arguments) {
  command.add_option("--epsilon", arguments.epsilon,
                     "Blend interval, relative to the nearest distance (Eq. 1); above 0, or the nearest layer is "
                     "outside its own interval")
      ->capture_default_str()->check(within(kEpsilonRange))->group("Blend");
  command.add_option("--min-weight-distance", arguments.minimumWeightDistance,
                     "r_min of the weights 1/max(d, r_min), metres; from 1 mm (nearer, a reference at the viewer "
                     "outweighs what a float holds) to 10 km (beyond, every weight is the same)")
      ->capture_default_str()->check(within(kMinimumWeightDistanceRange))->group("Blend");
  command.add_option("--blend-weights", arguments.blendWeights,
                     "Weights within the interval: reliability (inverse distance times how well each reference sampled "
                     "the surface) or distance (inverse distance alone, the paper's)")
      ->capture_default_str()->check(CLI::IsMember({"reliability", "distance"}))->group("Blend");
}

}  // namespace

void addRenderQualityOptions(CLI::App& command, QualityArguments& arguments, SourceMesh mesh) {
  addStretchOptions(command, arguments);
  arguments.sourceMesh = sourceMeshName(mesh);
  addSourceMeshOptions(command, arguments);
  addBlendOptions(command, arguments);
  addHoleOption(command, arguments, HoleMode::Fill,
                "Holes after the blend: fill (push-pull from the background), mark (magenta) or black");
}

void addQualityOptions(CLI::App& command, QualityArguments& arguments, HoleMode holes) {
  addStretchOptions(command, arguments);
  command.add_flag("--point-warp", arguments.pointWarp, "The paper's literal point warp instead of the triangle mesh")
      ->group("Warp");
  addSourceMeshOptions(command, arguments);
  addBlendOptions(command, arguments);
  addHoleOption(command, arguments, holes,
                "Holes after the blend: fill (the error sees the filled view, as a walker does), or mark / black "
                "(the raw warp: holes count as black and as bad pixels, the paper's)");
  command.add_option("--alpha", arguments.alpha,
                     "Weight of R in E = alpha R + beta B (0 to 1e6: beyond, a weight only rescales E, and the bound "
                     "keeps every sum of errors finite)")
      ->capture_default_str()->check(within(kErrorWeightRange))->group("Error");
  command.add_option("--beta", arguments.beta, "Weight of B (percent of bad pixels; 0 to 1e6, as --alpha)")
      ->capture_default_str()->check(within(kErrorWeightRange))->group("Error");
  command.add_option("--delta", arguments.delta, "Bad-pixel tolerance on the 0..255 scale (past 255 no pixel is bad)")
      ->capture_default_str()->check(within(kBadPixelToleranceRange))->group("Error");
  command.add_option("--pixel-weighting", arguments.pixelWeighting, "solid-angle (panoramas) or uniform (the paper's)")
      ->capture_default_str()->check(CLI::IsMember({"solid-angle", "uniform"}))->group("Error");
}

SynthesisOptions synthesisOptions(const QualityArguments& arguments) {
  SynthesisOptions options;
  options.warp.method = arguments.pointWarp ? WarpMethod::Point : WarpMethod::Mesh;
  options.warp.stretchTest = parseStretchTest(arguments.stretchTest);
  options.warp.grazingAngleDegrees = arguments.grazingAngleDegrees;
  options.warp.maxDepthRatio = arguments.maxDepthRatio;
  options.warp.mesh = parseSourceMesh(arguments.sourceMesh);
  options.warp.meshTolerancePixels = arguments.meshTolerancePixels;
  options.blend.epsilon = arguments.epsilon;
  options.blend.minimumWeightDistance = arguments.minimumWeightDistance;
  options.blend.weights = parseBlendWeights(arguments.blendWeights);
  options.holes = parseHoleMode(arguments.holes);
  return options;
}

ErrorOptions errorOptions(const QualityArguments& arguments) {
  ErrorOptions options;
  options.alpha = arguments.alpha;
  options.beta = arguments.beta;
  options.delta = arguments.delta;
  options.weighting = parsePixelWeighting(arguments.pixelWeighting);
  return options;
}

std::string describeQuality(const SynthesisOptions& synthesis, const ErrorOptions& error) {
  char text[400];
  const WarpOptions& warp = synthesis.warp;
  char stretch[64];
  if (warp.stretchTest == StretchTest::GrazingAngle) {
    std::snprintf(stretch, sizeof stretch, "grazing-angle %.1f deg", warp.grazingAngleDegrees);
  } else if (warp.stretchTest == StretchTest::DepthRatio) {
    std::snprintf(stretch, sizeof stretch, "depth-ratio %.2f", warp.maxDepthRatio);
  } else {
    std::snprintf(stretch, sizeof stretch, "no stretch test");
  }
  char mesh[64] = "";
  if (warp.mesh == SourceMesh::Simplified) {
    std::snprintf(mesh, sizeof mesh, ", simplified %.2f px mesh", warp.meshTolerancePixels);
  }
  std::snprintf(text, sizeof text,
                "warp %s (%s%s); blend epsilon %.3f, r_min %.2f m, %s weights; holes %s; error E = %g R + %g B, delta "
                "%g/255, %s pixel weighting",
                warp.method == WarpMethod::Mesh ? "mesh" : "point", stretch, mesh, synthesis.blend.epsilon,
                synthesis.blend.minimumWeightDistance, blendWeightsName(synthesis.blend.weights),
                synthesis.holes == HoleMode::Fill ? "filled" : "raw", error.alpha, error.beta, error.delta,
                pixelWeightingName(error.weighting));
  return text;
}

}  // namespace triwalk
