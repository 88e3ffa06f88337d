#include "core/synthesis/view_synthesis.h"

#include <algorithm>

namespace triwalk {

SynthesizedView synthesizeView(std::span<const WarpSource* const> sources, const DestinationCamera& destination,
                               const SynthesisOptions& options) {
  SynthesizedView view;
  std::vector<glm::vec3> positions;
  for (const WarpSource* source : sources) {
    view.layers.push_back(warpToCamera(*source, destination, options.warp.method));
    positions.push_back(source->position());
  }
  const std::vector<float> weights = blendWeights(destination.position, positions, options.blend);
  std::vector<const WarpLayer*> layers;
  for (const WarpLayer& layer : view.layers) layers.push_back(&layer);
  view.blended = blendLayers(layers, weights, options.blend);
  if (options.holes == HoleMode::Fill) {
    view.fill = fillHoles(view.blended, options.blend.epsilon);
  } else {
    view.fill.holesBefore = view.fill.unfilled =
        size_t(std::count(view.blended.hole.begin(), view.blended.hole.end(), uint8_t(1)));
  }
  return view;
}

}  // namespace triwalk
