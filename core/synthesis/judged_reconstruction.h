#pragma once
// A view reconstructed from references at a position and judged against
// the truth there: what a selection's probe error is made of, what `synth`
// prints and writes, and what the viewer's inspector shows. One function,
// so the three cannot drift apart.

#include "core/image/image.h"
#include "core/synthesis/reconstruction_error.h"
#include "core/synthesis/view_synthesis.h"

#include <span>

namespace triwalk {

struct JudgedReconstruction {
  SynthesizedView view;
  ReconstructionError error;
  ScalarImage perPixel;  // each pixel's RMS colour difference (1 at holes), when kept
};

enum class PerPixelError { Kept, Skipped };

// The panorama at position, width x width / 2, synthesized from sources,
// and its error against truthDisplay (display colours, the same size).
JudgedReconstruction reconstructAndJudge(std::span<const WarpSource* const> sources, glm::vec3 position, int width,
                                         const ColorImage& truthDisplay, const SynthesisOptions& synthesis,
                                         const ErrorOptions& error, PerPixelError perPixel = PerPixelError::Kept);

}  // namespace triwalk
