#pragma once
// The error of one row of a reconstruction blended from cached layers,
// without building the blended image: per pixel, blendPixelOf over the
// decoded layer rows, the blended colour in display colours
// (displayColorFast), compared with the truth (ErrorAccumulator::add).
// Four pixels at a time, lane by lane the same operations in the same
// order as those functions, so the same bits (tests/blended_row_error_test.cpp).
// Every error the selection computes passes through here: the blend and
// the comparison pixel by pixel were the largest part of a decimation
// (docs/history/BENCHMARKS-2026-11.md).

#include "core/synthesis/blend.h"
#include "core/synthesis/reconstruction_error.h"
#include "core/synthesis/warp_layer_cache.h"

#include <span>

namespace triwalk {

// Adds row y to accumulator: pixel i of the row blends pixel i of every
// layer (at most 8, all as long as the row) with weights (blendWeights),
// and is compared with truth[i * truthStride] (display colours).
void addBlendedRowError(std::span<const DecodedLayerRow* const> layers, std::span<const float> weights,
                        const BlendOptions& options, const glm::vec3* truth, size_t truthStride, int y,
                        ErrorAccumulator& accumulator);

}  // namespace triwalk
