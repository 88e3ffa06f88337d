// Half-float conversion of arrays (core/image/half_float.h): the F16C path
// gives Imath's floats for every half and Imath's halves for floats at and
// around every rounding boundary, so the cached layers' values do not
// depend on the processor.

#include "core/image/half_float.h"
#include "tests/test_support.h"

#include <Imath/half.h>

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace triwalk;

namespace {

bool isNanHalf(uint16_t bits) { return (bits & 0x7fff) > 0x7c00; }

// Every half's value, the midpoints between neighbouring halves (where
// rounding to the nearest even decides), the floats either side of each,
// the edges of overflow and underflow, and random floats.
std::vector<float> boundaryFloats() {
  std::vector<float> floats;
  for (uint32_t bits = 0; bits < 0x7c00; ++bits) {
    const double value = double(imath_half_to_float(uint16_t(bits)));
    const double next = double(imath_half_to_float(uint16_t(bits + 1)));
    const float midpoint = float(0.5 * (value + next));  // exact: a half's mantissa and one bit more
    for (float f : {float(value), midpoint, std::nextafter(midpoint, 0.0f), std::nextafter(midpoint, 1e9f)}) {
      floats.push_back(f);
      floats.push_back(-f);
    }
  }
  const float infinity = std::numeric_limits<float>::infinity();
  for (float f : {65519.0f, 65520.0f, 65536.0f, 1e10f, infinity, 3e-8f, 2.98e-8f, 5.96e-8f, 1e-45f, 0.0f}) {
    floats.push_back(f);
    floats.push_back(-f);
  }
  std::mt19937 random(3);
  std::uniform_int_distribution<uint32_t> bits;
  for (int i = 0; i < 1000000; ++i) {
    const float f = std::bit_cast<float>(bits(random));
    if (!std::isnan(f)) floats.push_back(f);
  }
  return floats;
}

}  // namespace

TEST_CASE("halves to floats: the portable path gives Imath's value for every half, and F16C the same") {
  std::vector<uint16_t> halves(65536);
  for (size_t i = 0; i < halves.size(); ++i) halves[i] = uint16_t(i);
  std::vector<float> portable(halves.size()), best(halves.size());
  halvesToFloats(halves, portable, HalfConversion::Portable);
  halvesToFloats(halves, best);
  for (size_t i = 0; i < halves.size(); ++i) {
    Imath::half h;
    h.setBits(halves[i]);
    const float expected = float(h);
    INFO("half bits " << i);
    if (isNanHalf(halves[i])) {
      CHECK(std::isnan(portable[i]));
      CHECK(std::isnan(best[i]));
    } else {
      CHECK(testing::sameBits(portable[i], expected));
      CHECK(testing::sameBits(best[i], expected));
    }
  }
  if (!hardwareHalfConversion()) MESSAGE("this processor has no F16C: only the portable path was checked");
}

TEST_CASE("floats to halves: rounded to the nearest even, the same by either path") {
  const std::vector<float> floats = boundaryFloats();
  std::vector<uint16_t> portable(floats.size()), best(floats.size());
  floatsToHalves(floats, portable, HalfConversion::Portable);
  floatsToHalves(floats, best);
  size_t differences = 0, wrong = 0;
  for (size_t i = 0; i < floats.size(); ++i) {
    differences += portable[i] != best[i];
    wrong += portable[i] != Imath::half(floats[i]).bits();
  }
  CHECK(differences == 0);
  CHECK(wrong == 0);
  // The ties go to the even half: 1 + 2^-11 lies halfway between 1 and the
  // next half, whose last bit is odd.
  const std::vector<float> ties = {1.0f + 0x1p-11f, 1.0f + 3.0f * 0x1p-11f};
  std::vector<uint16_t> rounded(2);
  floatsToHalves(ties, rounded);
  CHECK(rounded[0] == 0x3c00);
  CHECK(rounded[1] == 0x3c02);
  // A NaN stays a NaN, whatever its payload.
  const std::vector<float> nan = {std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::quiet_NaN()};
  std::vector<uint16_t> nanHalves(2);
  floatsToHalves(nan, nanHalves);
  CHECK(isNanHalf(nanHalves[0]));
  CHECK(isNanHalf(nanHalves[1]));
}
