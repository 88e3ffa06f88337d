#include "core/synthesis/view_synthesis.h"

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
  return view;
}

}  // namespace triwalk
