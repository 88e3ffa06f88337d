// The panorama projection's arc tangents (core/geometry/float_arc_tangent.h)
// and its four-lane image points: the lanes give the scalar function's
// bits, every special case included, and both are accurate.

#include "core/geometry/float_arc_tangent.h"
#include "core/geometry/projection.h"

#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace triwalk;

namespace {

// Values that take every case of atan2Float, and ordinary ones between.
std::vector<float> awkwardValues() {
  const float infinity = std::numeric_limits<float>::infinity();
  std::vector<float> values = {0.0f,      -0.0f,     1.0f,       -1.0f,  infinity, -infinity,
                               std::numeric_limits<float>::quiet_NaN(),  1e-30f,   -1e-30f,   1e30f,
                               -1e30f,    0.4375f,   0.6875f,    1.1875f, 2.4375f,  3e-9f,
                               1e-45f,    0.3f,      -2.0f,      7.5f,    -0.01f,   std::nextafter(1.0f, 2.0f)};
  return values;
}

}  // namespace

TEST_CASE("the arc tangents agree with double precision to a float's rounding") {
  std::mt19937 random(5);
  std::uniform_real_distribution<float> uniform(-40.0f, 40.0f);
  for (int i = 0; i < 200000; ++i) {
    const float y = uniform(random), x = uniform(random);
    const double exact = std::atan2(double(y), double(x));
    CHECK(std::abs(double(atan2Float(y, x)) - exact) <= 4.0 * std::abs(exact) * 0x1p-24 + 1e-30);  // 2 ulp
    const double length = std::hypot(double(x), double(y));
    CHECK(std::abs(double(hypotFloat(x, y)) - length) <= length * 0x1p-24);
  }
  for (const float x : awkwardValues()) {
    if (std::isnan(x) || std::isinf(x)) continue;
    CHECK(std::abs(double(atanFloat(x)) - std::atan(double(x))) <= 4.0 * std::abs(std::atan(double(x))) * 0x1p-24);
  }
  CHECK(atan2Float(0.0f, -1.0f) == doctest::Approx(kPi));
  CHECK(atan2Float(-1.0f, 0.0f) == doctest::Approx(-kPi / 2));
  CHECK(std::isnan(atan2Float(std::numeric_limits<float>::quiet_NaN(), 1.0f)));
}

#if defined(__GLIBC__) && __GLIBC__ == 2 && __GLIBC_MINOR__ == 36
// Debian bookworm: the functions are the C library's, bit for bit, so the
// projection (and every selection made before they were written out) is
// what it was with std::atan2 and std::hypot.
TEST_CASE("the arc tangents give glibc 2.36's bits") {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> uniform(-40.0f, 40.0f);
  for (int i = 0; i < 1000000; ++i) {
    const float y = i % 2 ? uniform(random) : std::bit_cast<float>(uint32_t(random()));
    const float x = i % 2 ? uniform(random) : std::bit_cast<float>(uint32_t(random()));
    if (std::isnan(x) || std::isnan(y)) continue;
    REQUIRE(testing::sameBits(atan2Float(y, x), std::atan2(y, x)));
    REQUIRE(testing::sameBits(atanFloat(x), std::atan(x)));
    REQUIRE(testing::sameBits(hypotFloat(x, y), std::hypot(x, y)));
  }
  for (const float y : awkwardValues()) {
    for (const float x : awkwardValues()) {
      if (std::isnan(x) || std::isnan(y)) continue;
      CHECK(testing::sameBits(atan2Float(y, x), std::atan2(y, x)));
    }
  }
}
#endif

TEST_CASE("four-lane arc tangents give the scalar bits and flag the special cases") {
  const std::vector<float> values = awkwardValues();
  std::mt19937 random(11);
  std::uniform_real_distribution<float> uniform(-3.0f, 3.0f);
  int handled = 0, unhandledCount = 0;
  for (int round = 0; round < 20000; ++round) {
    Floats4 y, x;
    for (int lane = 0; lane < 4; ++lane) {
      // Mostly ordinary values, an awkward one in some lanes.
      const bool awkward = (round + lane) % 5 == 0;
      y[lane] = awkward ? values[size_t(random()) % values.size()] : uniform(random);
      x[lane] = (round + lane) % 7 == 0 ? values[size_t(random()) % values.size()] : uniform(random);
    }
    Masks4 unhandled = {0, 0, 0, 0};
    const Floats4 lanes = atan2Floats(y, x, unhandled);
    const Floats4 lengths = hypotFloats(x, y);
    for (int lane = 0; lane < 4; ++lane) {
      const bool special = std::isnan(x[lane]) || std::isnan(y[lane]) || std::isinf(x[lane]) || std::isinf(y[lane]) ||
                           x[lane] == 0.0f || y[lane] == 0.0f || x[lane] == 1.0f;
      const bool flagged = unhandled[lane] != 0;
      if (special) CHECK(flagged);
      if (std::isfinite(x[lane]) && std::isfinite(y[lane]))
        CHECK(testing::sameBits(lengths[lane], hypotFloat(x[lane], y[lane])));
      if (flagged) {
        ++unhandledCount;
        continue;
      }
      ++handled;
      CHECK(testing::sameBits(lanes[lane], atan2Float(y[lane], x[lane])));
    }
  }
  CHECK(handled > 40000);
  CHECK(unhandledCount > 4000);
}

TEST_CASE("image points four at a time are imagePoint's, seam, poles and axes included") {
  std::vector<glm::vec3> directions;
  std::mt19937 random(13);
  std::normal_distribution<float> normal;
  for (int i = 0; i < 4001; ++i) directions.emplace_back(normal(random), normal(random), normal(random));
  // Pixel centres (the seam's columns among them), axes, poles, and rays a
  // hair either side of the seam.
  for (const float yaw : {0.0f, 0.7f, -3.0f, 9.0f}) {
    const EquirectProjection grid{64, 32, yaw};
    for (int v = 0; v < 32; ++v) {
      for (int u = 0; u < 64; ++u) directions.push_back(grid.pixelDirection(u, v));
    }
  }
  for (const glm::vec3 axis : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0),
                               glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(0, 0, 0), glm::vec3(-1, 1e-30f, 0),
                               glm::vec3(-1, -1e-30f, 0), glm::vec3(-1, 0, 1), glm::vec3(1, 1, 1), glm::vec3(-1e-8f, 2e-8f, 5)}) {
    directions.push_back(axis);
    directions.push_back(3.5f * axis);
  }
  for (const float yaw : {0.0f, 0.7f, -3.0f, 9.0f}) {
    const EquirectProjection projection{256, 128, yaw};
    std::vector<glm::vec2> points(directions.size());
    projection.imagePoints(directions, points);
    for (size_t i = 0; i < directions.size(); ++i) {
      const glm::vec2 expected = projection.imagePoint(directions[i]);
      INFO("direction ", directions[i].x, " ", directions[i].y, " ", directions[i].z, ", yaw ", yaw);
      REQUIRE(testing::sameBits(points[i].x, expected.x));
      REQUIRE(testing::sameBits(points[i].y, expected.y));
      REQUIRE(points[i].x >= 0.0f);
      REQUIRE(points[i].x < 256.0f);
    }
  }
}
