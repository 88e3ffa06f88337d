#pragma once
// A novel view from reference panoramas: warp each, weight by distance to
// the destination, blend (docs/DESIGN.md, "Warp and blend"), fill the holes
// (docs/DESIGN.md, "Hole filling").

#include "core/synthesis/blend.h"
#include "core/synthesis/hole_fill.h"
#include "core/synthesis/warp.h"

#include <span>

namespace triwalk {

struct SynthesisOptions {
  WarpOptions warp;
  BlendOptions blend;
  // Fill: the holes are filled after the blend (what a walker sees, and
  // the error measured on it); Mark and Black leave them holes.
  HoleMode holes = HoleMode::Fill;
};

struct SynthesizedView {
  BlendedView blended;  // filled when the options ask
  std::vector<WarpLayer> layers;
  HoleFillStatistics fill;  // holes before the fill (counted in every mode) and after
};

SynthesizedView synthesizeView(std::span<const WarpSource* const> sources, const DestinationCamera& destination,
                               const SynthesisOptions& options);

}  // namespace triwalk
