#pragma once
// The pixels of a reference panorama whose colour mixes two surfaces.
//
// A capture's colour is anti-aliased (shaders/capture_equirect.frag: the
// mean of four samples inside the pixel) while its distance is one
// surface's (the nearest cube texel's plane), and a real camera blurs
// colour across a silhouette the same way. So the pixels beside a depth
// discontinuity carry some of the other surface's colour at this one's
// distance. Those of the farther surface (or the sky), warped to a view
// from elsewhere, put the nearer surface's colour on the surface behind
// the silhouette, away from it: a thin light strand across
// the ceiling and down a wall behind a pillar, grey lines across the sky
// behind a roof's edge (docs/RESULTS.md, "Artifacts"). The blend trusts
// these pixels least (core/synthesis/warp_reliability.h,
// fringeReliability), so a reference that saw the surface there cleanly
// takes over; where none did they still show, so no hole opens.

#include "core/image/image.h"
#include "core/synthesis/warp.h"

#include <cstdint>
#include <vector>

namespace triwalk {

// Distances further apart than this ratio are two surfaces: the depth-ratio
// stretch test's default, so the two agree on what a discontinuity is.
inline constexpr float kFringeDepthRatio = WarpOptions{}.maxDepthRatio;

// 1 for each pixel (row-major) that lies behind a pixel of its 3x3
// neighbourhood across a discontinuity: sky beside a surface, or a surface
// more than kFringeDepthRatio times farther. Columns wrap (the panorama is
// a full turn), rows stop at the poles. The mixing reaches one pixel: each
// of the four colour samples is bilinear over cube texels about two thirds
// of a panorama pixel wide. The nearer side's mixed pixels are not flagged:
// they land on that surface's own silhouette, where the view's truth mixes
// too (flagged as well, they raised probe errors on 128-pixel captures by
// 0.8% to 2.1%; docs/DESIGN.md, "Blend weights").
std::vector<uint8_t> silhouetteFringe(const ScalarImage& distance);

}  // namespace triwalk
