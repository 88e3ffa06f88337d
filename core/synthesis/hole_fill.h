#pragma once
// Filling the holes of a blended view (docs/DESIGN.md, "Hole filling"):
// pixels no reference covers after the warp, disocclusions behind
// foreground objects and pixels whose every triangle failed the stretch
// test. A push-pull pyramid that prefers the background:
//
//   push: level l+1 pixel from its (up to) 2x2 children at level l that are
//         valid; only the children on the farthest surface count (inverse
//         distance within (1 + epsilon) of the smallest, the blend's own
//         "same surface" interval; sky is farthest of all), averaged.
//   pull: from the coarsest level down, a pixel that is not valid takes the
//         bilinear interpolation (weights 9/16, 3/16, 3/16, 1/16) of its
//         four nearest coarser pixels, again only the valid ones on the
//         farthest surface, weights renormalized.
//
// So a hole beside a pillar is filled from the wall behind it, never from
// the pillar. Valid pixels are never changed. The GPU renderer runs the same
// passes (shaders/fill_push.frag, fill_pull.frag) on half floats.

#include "core/synthesis/blend.h"

#include <string>

namespace triwalk {

// What a rendered frame shows where the warp left a hole.
enum class HoleMode {
  Fill,   // push-pull fill from the background
  Mark,   // magenta, to see them
  Black,  // black, as the paper shows them
};

// Parses "fill", "mark", "black"; throws InputError naming the setting
// ("holes"; the command line says which option set it).
HoleMode parseHoleMode(const std::string& name);
const char* holeModeName(HoleMode mode);

// The display colour of a pixel left a hole: magenta to mark, else black.
glm::vec3 holeDisplayColor(HoleMode mode);

// A blended view in display bytes, the pixels still holes in
// holeDisplayColor(mode).
Rgb8Image displayImage(const BlendedView& view, HoleMode mode);

struct HoleFillStatistics {
  size_t holesBefore = 0;  // pixels that were holes before filling
  size_t unfilled = 0;     // pixels still holes after (only when nothing at all was covered)
};

// Fills view's holes in place (colour and distance); filled pixels stop
// being holes. epsilon: the blend's relative depth interval.
HoleFillStatistics fillHoles(BlendedView& view, float epsilon);

}  // namespace triwalk
