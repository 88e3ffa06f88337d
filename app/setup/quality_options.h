#pragma once
// The warp, blend and error options shared by synth, decimate, eval and
// render, registered once so every command names them the same way.

#include "core/synthesis/reconstruction_error.h"
#include "core/synthesis/view_synthesis.h"

#include <CLI/CLI.hpp>

#include <string>

namespace triwalk {

struct QualityArguments {
  std::string stretchTest = "grazing-angle";
  float grazingAngleDegrees = WarpOptions{}.grazingAngleDegrees;
  float maxDepthRatio = WarpOptions{}.maxDepthRatio;
  bool pointWarp = false;
  std::string sourceMesh = sourceMeshName(SourceMesh::Grid);
  float meshTolerancePixels = WarpOptions{}.meshTolerancePixels;
  float epsilon = BlendOptions{}.epsilon;
  float minimumWeightDistance = BlendOptions{}.minimumWeightDistance;
  std::string blendWeights = blendWeightsName(BlendOptions{}.weights);
  double alpha = ErrorOptions{}.alpha;
  double beta = ErrorOptions{}.beta;
  double delta = ErrorOptions{}.delta;
  std::string pixelWeighting = "solid-angle";
  std::string holes = "fill";  // the command's own default replaces it when registered
};

// Warp, blend, hole and error options (synth, decimate, eval); holes: the
// command's default for --holes (what the error is measured on).
void addQualityOptions(CLI::App& command, QualityArguments& arguments, HoleMode holes);
// The stretch test, the source mesh (the command's default), the blend and
// --holes (default fill) only (render, view: the GPU warp).
void addRenderQualityOptions(CLI::App& command, QualityArguments& arguments, SourceMesh mesh);

SynthesisOptions synthesisOptions(const QualityArguments& arguments);
ErrorOptions errorOptions(const QualityArguments& arguments);

// One line for reports: every choice that changes the numbers.
std::string describeQuality(const SynthesisOptions& synthesis, const ErrorOptions& error);

}  // namespace triwalk
