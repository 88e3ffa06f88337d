#pragma once
// The pixels of a reference panorama whose colour mixes two surfaces.
//
// A capture's colour is anti-aliased (shaders/capture_equirect.frag: the
// mean of four samples inside the pixel) while its distance is one
// surface's (the nearest cube texel's plane), and a real camera blurs
// colour across a silhouette the same way. So the pixels beside a depth
// discontinuity carry some of the other surface's colour at this one's
// distance. Warped to a view from elsewhere, that colour lands on the
// surface behind the silhouette, away from it: a thin light strand across
// the ceiling and down a wall behind a pillar, grey lines across the sky
// behind a roof's edge (docs/RESULTS.md, "Artifacts"). The blend trusts
// these pixels least (core/synthesis/warp_reliability.h,
// fringeReliability), so a reference that saw the surface there cleanly
// takes over; where none did they still show, so no hole opens.

#include "core/image/image.h"

#include <cstdint>
#include <vector>

namespace triwalk {

// Distances further apart than this ratio are two surfaces (the depth-ratio
// stretch test's own default, WarpOptions::maxDepthRatio).
inline constexpr float kFringeDepthRatio = 1.15f;

// 1 for each pixel (row-major) with a pixel of its 3x3 neighbourhood
// across a discontinuity from it: one at infinity (sky) and the other not,
// or distances more than kFringeDepthRatio apart. Columns wrap (the
// panorama is a full turn), rows stop at the poles. The mixing reaches one
// pixel either side: each of the four colour samples is bilinear over cube
// texels about two thirds of a panorama pixel wide (two pixels either side
// gained no PSNR on the main job's walks; docs/DESIGN.md, "Blend weights").
std::vector<uint8_t> silhouetteFringe(const ScalarImage& distance);

}  // namespace triwalk
