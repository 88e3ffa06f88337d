#include "core/synthesis/blended_row_error.h"

#include "core/image/color.h"
#include "core/support/errors.h"
#include "core/support/float_lanes.h"

#include <limits>

namespace triwalk {

namespace {

constexpr size_t kMaxLayers = 8;
constexpr size_t kBlockPixels = 64;  // differences handed to the accumulator at once

// linearToSrgbFast lane by lane (clamped to [0, 1], then the table's
// interpolation). The first test is written so that NaN (a blend with no
// weight) fails it and becomes 0: NaN passes every `<` clamp and would
// index the table with a garbage integer.
Floats4 displayChannel(Floats4 linear) {
  linear = linear >= 0.0f ? linear : splat(0.0f);
  linear = 1.0f < linear ? splat(1.0f) : linear;
  const Floats4 x = linear * float(kSrgbTableIntervals);
  const Masks4 index = __builtin_convertvector(x, Masks4);
  const float* table = srgbTable();
  const Floats4 below = {table[index[0]], table[index[1]], table[index[2]], table[index[3]]};
  const Floats4 above = {table[index[0] + 1], table[index[1] + 1], table[index[2] + 1], table[index[3] + 1]};
  return below + (x - __builtin_convertvector(index, Floats4)) * (above - below);
}

struct Blended4 {
  Floats4 red, green, blue;  // linear; 0 in holes
  Masks4 hole;
};

// blendPixelOf for pixels [pixel, pixel + 4).
Blended4 blend4(std::span<const DecodedLayerRow* const> layers, std::span<const float> weights,
                const BlendOptions& options, size_t pixel) {
  const float infinity = std::numeric_limits<float>::infinity();
  Floats4 distances[kMaxLayers];
  Floats4 front = splat(infinity);
  Masks4 covered = {0, 0, 0, 0};
  for (size_t k = 0; k < layers.size(); ++k) {
    const Floats4 d = loadFloats4(&layers[k]->distance[pixel]);  // NaN where not covered
    distances[k] = d;
    covered |= d == d;
    front = d < front ? d : front;  // std::min(front, d)
  }
  const Masks4 frontIsInfinite = absolute(front) == infinity;
  const Floats4 interval = options.epsilon * front;
  Floats4 red = splat(0.0f), green = red, blue = red, weightSum = red;
  for (size_t k = 0; k < layers.size(); ++k) {
    const DecodedLayerRow& layer = *layers[k];
    const Floats4 d = distances[k];
    // A NaN (not covered) is neither infinite nor within the interval.
    const Masks4 inInterval = frontIsInfinite ? absolute(d) == infinity : absolute(d - front) < interval;
    const Floats4 weight = options.weights == BlendWeights::Reliability && !layer.reliability.empty()
                               ? weights[k] * loadFloats4(&layer.reliability[pixel])
                               : splat(weights[k]);
    red = inInterval ? red + weight * loadFloats4(&layer.red[pixel]) : red;
    green = inInterval ? green + weight * loadFloats4(&layer.green[pixel]) : green;
    blue = inInterval ? blue + weight * loadFloats4(&layer.blue[pixel]) : blue;
    weightSum = inInterval ? weightSum + weight : weightSum;
  }
  const Floats4 zero = splat(0.0f);
  return {covered ? red / weightSum : zero, covered ? green / weightSum : zero, covered ? blue / weightSum : zero,
          ~covered};
}

}  // namespace

void addBlendedRowError(std::span<const DecodedLayerRow* const> layers, std::span<const float> weights,
                        const BlendOptions& options, const glm::vec3* truth, size_t truthStride, int y,
                        ErrorAccumulator& accumulator) {
  TRIWALK_CHECK(!layers.empty() && layers.size() <= kMaxLayers && weights.size() == layers.size(),
                "one weight for each of at most 8 layers");
  const size_t count = layers[0]->distance.size();
  for (const DecodedLayerRow* layer : layers) TRIWALK_CHECK(layer->distance.size() == count, "rows of one length");
  float squared[kBlockPixels], largest[kBlockPixels];
  uint8_t hole[kBlockPixels];
  size_t pixel = 0;
  while (pixel + 4 <= count) {
    const size_t block = std::min(kBlockPixels, (count - pixel) / 4 * 4);
    for (size_t lane = 0; lane < block; lane += 4, pixel += 4) {
      const Blended4 blended = blend4(layers, weights, options, pixel);
      // ErrorAccumulator::add: holes compare black with the truth.
      const auto difference = [&](Floats4 linear, int channel) {
        const Floats4 truthLanes = {truth[pixel * truthStride][channel], truth[(pixel + 1) * truthStride][channel],
                                    truth[(pixel + 2) * truthStride][channel], truth[(pixel + 3) * truthStride][channel]};
        return absolute((blended.hole ? splat(0.0f) : displayChannel(linear)) - truthLanes);
      };
      const Floats4 red = difference(blended.red, 0), green = difference(blended.green, 1),
                    blue = difference(blended.blue, 2);
      storeFloats4(red * red + green * green + blue * blue, &squared[lane]);  // glm::dot's order
      const Floats4 greenOrBlue = green < blue ? blue : green;                 // std::max(g, b)
      storeFloats4(red < greenOrBlue ? greenOrBlue : red, &largest[lane]);
      for (size_t i = 0; i < 4; ++i) hole[lane + i] = blended.hole[i] != 0;
    }
    accumulator.addRow(y, std::span(squared, block), std::span(largest, block), std::span(hole, block));
  }
  // The last pixels of a row whose length is not a multiple of four.
  for (; pixel < count; ++pixel) {
    const BlendedPixel blended = blendPixelOf<DecodedLayerRow>(layers, weights, pixel, options);
    accumulator.add(y, displayColorFast(blended.color), blended.hole, truth[pixel * truthStride]);
  }
}

}  // namespace triwalk
