#include "core/synthesis/judged_reconstruction.h"

#include "core/image/color.h"

namespace triwalk {

JudgedReconstruction reconstructAndJudge(std::span<const WarpSource* const> sources, glm::vec3 position, int width,
                                         const ColorImage& truthDisplay, const SynthesisOptions& synthesis,
                                         const ErrorOptions& error, PerPixelError perPixel) {
  JudgedReconstruction result;
  result.view = synthesizeView(sources, DestinationCamera::panorama(position, width, width / 2), synthesis);
  result.error = reconstructionError(toDisplayColors(result.view.blended.color), result.view.blended.hole, truthDisplay,
                                     error, perPixel == PerPixelError::Kept ? &result.perPixel : nullptr);
  return result;
}

}  // namespace triwalk
