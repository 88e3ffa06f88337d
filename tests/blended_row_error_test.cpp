// The selection's row error in four lanes (core/synthesis/blended_row_error.h)
// against the pixel-by-pixel functions it stands for: blendPixelOf,
// displayColorFast and ErrorAccumulator::add. The same sums to the bit, on
// rows that take every case of the blend: holes, sky, distances on either
// side of the epsilon interval, colours outside [0, 1], reliability or
// none, one to eight layers, rows whose length is not a multiple of four.

#include "core/image/color.h"
#include "core/synthesis/blended_row_error.h"

#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace triwalk;

namespace {

// A row of `count` pixels in `layerCount` layers: per pixel a front
// distance, and each layer uncovered, sky, at the front, just inside or
// just outside the interval, or far behind; or a hole or sky in every layer.
std::vector<DecodedLayerRow> awkwardRows(std::mt19937& random, size_t layerCount, size_t count, float epsilon,
                                         bool withReliability) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), colour(-0.1f, 1.2f), front(0.05f, 30.0f);
  std::uniform_int_distribution<int> kind(0, 7);
  const float infinity = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<DecodedLayerRow> rows(layerCount);
  for (DecodedLayerRow& row : rows) {
    for (auto* plane : {&row.red, &row.green, &row.blue, &row.distance}) plane->resize(count);
    if (withReliability) row.reliability.resize(count);
  }
  for (size_t i = 0; i < count; ++i) {
    const float f = front(random);
    const int whole = kind(random);  // 0: a hole in every layer, 1: sky in every layer
    for (DecodedLayerRow& row : rows) {
      const float boundary = f + epsilon * f;
      float d = nan;
      switch (whole <= 1 ? whole : kind(random)) {
        case 0: d = nan; break;
        case 1: d = infinity; break;
        case 2: d = f; break;
        case 3: d = std::nextafter(boundary, 0.0f); break;
        case 4: d = boundary; break;
        case 5: d = std::nextafter(boundary, infinity); break;
        case 6: d = f * (1.0f + epsilon * unit(random)); break;
        default: d = 3.0f * f; break;
      }
      row.distance[i] = d;
      row.red[i] = colour(random);
      row.green[i] = kind(random) == 0 ? 0.0f : colour(random);
      row.blue[i] = kind(random) == 0 ? 1.0f : colour(random);
      if (withReliability) row.reliability[i] = unit(random);
    }
  }
  return rows;
}

}  // namespace

TEST_CASE("a row's error in four lanes: the same sums as blending and comparing pixel by pixel") {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> truthColour(0.0f, 1.0f), weight(0.05f, 10.0f);
  int rowsChecked = 0, rowsWithHoles = 0;
  for (size_t layerCount : {1, 2, 3, 5, 8}) {
    for (size_t count : {1, 3, 4, 7, 64, 65, 130, 256}) {
      for (BlendWeights weights : {BlendWeights::Distance, BlendWeights::Reliability}) {
        for (bool withReliability : {false, true}) {
          for (size_t truthStride : {1, 2}) {
            BlendOptions options;
            options.weights = weights;
            const std::vector<DecodedLayerRow> rows = awkwardRows(random, layerCount, count, options.epsilon, withReliability);
            std::vector<const DecodedLayerRow*> layers;
            std::vector<float> layerWeights;
            for (const DecodedLayerRow& row : rows) layers.push_back(&row), layerWeights.push_back(weight(random));
            std::vector<glm::vec3> truth(count * truthStride);
            for (glm::vec3& t : truth) t = {truthColour(random), truthColour(random), truthColour(random)};

            const int width = int(count * truthStride), height = 4, y = 2;
            ErrorAccumulator lanes(width, height, ErrorOptions{}), expected(width, height, ErrorOptions{});
            addBlendedRowError(layers, layerWeights, options, truth.data(), truthStride, y, lanes);
            bool anyHole = false;
            for (size_t i = 0; i < count; ++i) {
              const BlendedPixel pixel = blendPixelOf<DecodedLayerRow>(layers, layerWeights, i, options);
              expected.add(y, displayColorFast(pixel.color), pixel.hole, truth[i * truthStride]);
              anyHole |= pixel.hole;
            }
            INFO(layerCount << " layers, " << count << " pixels, stride " << truthStride);
            CHECK(testing::sameBits(lanes.result().rms, expected.result().rms));
            CHECK(testing::sameBits(lanes.result().badPercent, expected.result().badPercent));
            CHECK(lanes.result().total > 0.0);
            ++rowsChecked;
            rowsWithHoles += anyHole;
          }
        }
      }
    }
  }
  CHECK(rowsChecked == 5 * 8 * 2 * 2 * 2);
  CHECK(rowsWithHoles > rowsChecked / 4);  // the holes' case was taken
}

TEST_CASE("a row's error in four lanes: one pixel at a time, each case alone") {
  // One pixel of two layers per case, padded to four lanes with copies,
  // so that a wrong lane shows as a wrong sum of that case.
  const float infinity = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const BlendOptions options;
  const float front = 2.0f, boundary = front + options.epsilon * front;
  const std::vector<std::pair<float, float>> cases = {
      {nan, nan},      {infinity, nan}, {infinity, infinity}, {front, infinity},
      {front, boundary}, {front, std::nextafter(boundary, 0.0f)}, {front, nan}, {nan, front}};
  const std::vector<float> weights = {1.0f, 3.0f};
  for (const auto& [first, second] : cases) {
    DecodedLayerRow rows[2];
    for (int k = 0; k < 2; ++k) {
      rows[k].distance.assign(4, k == 0 ? first : second);
      rows[k].red.assign(4, k == 0 ? 0.2f : 0.9f);
      rows[k].green.assign(4, 1.5f);
      rows[k].blue.assign(4, k == 0 ? -0.5f : 0.6f);
    }
    const DecodedLayerRow* layers[2] = {&rows[0], &rows[1]};
    const std::vector<glm::vec3> truth(4, glm::vec3(0.5f, 0.4f, 0.3f));
    ErrorAccumulator lanes(4, 1, ErrorOptions{}), expected(4, 1, ErrorOptions{});
    addBlendedRowError(layers, weights, options, truth.data(), 1, 0, lanes);
    for (size_t i = 0; i < 4; ++i) {
      const BlendedPixel pixel = blendPixelOf<DecodedLayerRow>(layers, weights, i, options);
      expected.add(0, displayColorFast(pixel.color), pixel.hole, truth[i]);
    }
    INFO("distances " << first << ", " << second);
    CHECK(testing::sameBits(lanes.result().total, expected.result().total));
  }
}

TEST_CASE("a pixel the blend gives no weight is an error like black, not an index far outside the sRGB table") {
  // An empty interval (epsilon 0) leaves every covered pixel without a
  // weight: its colour is 0 / 0. The lookup clamped with `<`, which NaN
  // passes, and indexed the table with it (a segmentation fault reached
  // from `decimate --epsilon 0` and from views at x = 1e30).
  const float nan = std::numeric_limits<float>::quiet_NaN();
  CHECK(linearToSrgbFast(nan) == 0.0f);
  CHECK(toBytes(glm::vec3(nan)) == glm::u8vec3(0));
  BlendOptions options;
  options.epsilon = 0.0f;
  DecodedLayerRow rows[2];
  for (int k = 0; k < 2; ++k) {
    rows[k].distance.assign(8, 2.0f + float(k));
    rows[k].red.assign(8, 0.7f);
    rows[k].green.assign(8, 0.7f);
    rows[k].blue.assign(8, 0.7f);
  }
  const DecodedLayerRow* layers[2] = {&rows[0], &rows[1]};
  const std::vector<float> weights = {1.0f, 1.0f};
  const std::vector<glm::vec3> truth(8, glm::vec3(0.5f)), black(8, glm::vec3(0.0f));
  ErrorAccumulator blended(8, 1, ErrorOptions{}), againstBlack(8, 1, ErrorOptions{});
  addBlendedRowError(layers, weights, options, truth.data(), 1, 0, blended);
  for (size_t i = 0; i < 8; ++i) againstBlack.add(0, glm::vec3(0.0f), false, truth[i]);
  CHECK(std::isfinite(blended.result().total));
  CHECK(blended.result().total == againstBlack.result().total);
}
