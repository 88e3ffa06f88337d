// The silhouette fringe (core/synthesis/silhouette_fringe.h) on distance
// images whose answer is known, and the reliability it gives a warped pixel.

#include "core/synthesis/silhouette_fringe.h"
#include "core/synthesis/warp.h"
#include "core/synthesis/warp_reliability.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace triwalk {

TEST_CASE("the silhouette fringe is the pixels just behind a depth step or at the sky's edge, across the seam too") {
  // Two surfaces, 1 m and 2 m away, side by side in a 6 x 3 panorama:
  // columns 0-2 near, 3-5 far. The steps are between columns 2 and 3 and,
  // across the panorama's seam, between 5 and 0: the far surface's pixels
  // beside them are the fringe, the near surface's are not.
  ScalarImage step(6, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 6; ++x) step.at(x, y) = x < 3 ? 1.0f : 2.0f;
  }
  const std::vector<uint8_t> fringe = silhouetteFringe(step);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 6; ++x) {
      INFO("pixel " << x << ", " << y);
      CHECK(fringe[size_t(y * 6 + x)] == (x == 3 || x == 5 ? 1 : 0));
    }
  }

  // One pixel of sky in a wall: the sky pixel alone (the wall around it is
  // in front of it).
  ScalarImage sky(7, 5, 3.0f);
  sky.at(3, 2) = std::numeric_limits<float>::infinity();
  const std::vector<uint8_t> around = silhouetteFringe(sky);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) {
      INFO("pixel " << x << ", " << y);
      CHECK(around[size_t(y * 7 + x)] == (x == 3 && y == 2 ? 1 : 0));
    }
  }

  // A surface receding smoothly (each column 10% farther than the last,
  // round the seam and back; the second row 4% farther), and the sky
  // alone: one surface each, no fringe.
  ScalarImage ramp(8, 2);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 8; ++x) ramp.at(x, y) = std::pow(1.1f, float(std::min(x, 8 - x))) * (y == 0 ? 1.0f : 1.04f);
  }
  for (const uint8_t flag : silhouetteFringe(ramp)) CHECK(flag == 0);
  for (const uint8_t flag : silhouetteFringe(ScalarImage(4, 2, std::numeric_limits<float>::infinity()))) {
    CHECK(flag == 0);
  }
}

TEST_CASE("a pixel drawn from the fringe counts least in the blend, and elsewhere the reliability is unchanged") {
  CHECK(fringeReliability(0.6f, 0.0f) == 0.6f);
  CHECK(fringeReliability(0.6f, 0.25f) == kMinimumReliability);
  CHECK(fringeReliability(1.0f, 1.0f) == kMinimumReliability);

  // A warp source carries its panorama's fringe per vertex: the grid's
  // vertex i is pixel i, the poles are never fringe. One near pixel: the
  // eight behind it around it are the fringe.
  Panorama panorama{ColorImage(8, 4, glm::vec3(0.5f)), ScalarImage(8, 4, 2.0f)};
  panorama.distance.at(5, 1) = 1.0f;
  const WarpSource source(panorama, glm::vec3(0.0f), 0.0f, WarpOptions{});
  CHECK(source.fringe(1 * 8 + 5) == 0.0f);
  CHECK(source.fringe(2 * 8 + 6) == 1.0f);
  CHECK(source.fringe(0 * 8 + 4) == 1.0f);
  CHECK(source.fringe(3 * 8 + 5) == 0.0f);
  CHECK(source.fringe(8 * 4) == 0.0f);
  CHECK(source.fringe(8 * 4 + 1) == 0.0f);
}

}  // namespace triwalk
