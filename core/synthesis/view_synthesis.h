#pragma once
// A novel view from reference panoramas: warp each, weight by distance to
// the destination, blend (docs/DESIGN.md, "Warp and blend").

#include "core/synthesis/blend.h"
#include "core/synthesis/warp.h"

#include <span>

namespace triwalk {

struct SynthesisOptions {
  WarpOptions warp;
  BlendOptions blend;
};

struct SynthesizedView {
  BlendedView blended;
  std::vector<WarpLayer> layers;
};

SynthesizedView synthesizeView(std::span<const WarpSource* const> sources, const DestinationCamera& destination,
                               const SynthesisOptions& options);

}  // namespace triwalk
