// The hole fill (core/synthesis/hole_fill.h) on cases with known answers:
// a pillar's disocclusion filled from the wall behind it, frames without
// holes left alone, frames with nothing known left unfilled, sky taken as
// the farthest surface except where surfaces outnumber it.

#include "core/support/errors.h"
#include "core/synthesis/hole_fill.h"
#include "core/synthesis/view_synthesis.h"
#include "tests/analytic_scene.h"

#include <doctest/doctest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

namespace triwalk {

namespace {

constexpr glm::vec3 kPillarColor(0.9f, 0.1f, 0.1f);

// A closed room with one red pillar; walls, floor and ceiling in smooth
// greens and blues (no red).
testing::AnalyticScene pillarRoom() {
  testing::AnalyticScene scene;
  scene.room = testing::AnalyticScene::Room{{-3.0f, -3.0f, 0.0f}, {3.0f, 3.0f, 2.8f}, false};
  scene.cylinders.push_back({{0.0f, 1.0f}, 0.3f, 0.0f, 2.8f});
  scene.shade = [](glm::vec3 point, int surface) {
    if (surface >= 200) return kPillarColor;
    return glm::vec3(0.15f, 0.5f + 0.1f * std::sin(point.x + point.z), 0.4f + 0.1f * std::cos(point.y));
  };
  return scene;
}

struct PillarWarp {
  SynthesizedView raw, filled;
  Panorama truth;
};

// The room seen from (0.8, -1) warped from one reference at (0, -1): the
// wall the pillar hides from the reference shows beside it.
PillarWarp warpPastPillar(float epsilon) {
  const testing::AnalyticScene scene = pillarRoom();
  const glm::vec3 reference(0.0f, -1.0f, 1.5f), destination(0.8f, -1.0f, 1.5f);
  const int width = 256;
  const WarpSource source(testing::renderPanorama(scene, reference, width), reference, 0.0f, WarpOptions{});
  const WarpSource* sources[] = {&source};
  SynthesisOptions options;
  options.blend.epsilon = epsilon;
  options.holes = HoleMode::Mark;
  PillarWarp result;
  result.raw = synthesizeView(sources, DestinationCamera::panorama(destination, width, width / 2), options);
  options.holes = HoleMode::Fill;
  result.filled = synthesizeView(sources, DestinationCamera::panorama(destination, width, width / 2), options);
  result.truth = testing::renderPanorama(scene, destination, width);
  return result;
}

}  // namespace

TEST_CASE("a pillar's disocclusion is filled with the wall behind it, not the pillar") {
  const PillarWarp warp = warpPastPillar(BlendOptions{}.epsilon);
  const BlendedView& raw = warp.raw.blended;
  const BlendedView& filled = warp.filled.blended;
  REQUIRE(warp.filled.fill.holesBefore > 100);
  CHECK(warp.filled.fill.holesBefore == warp.raw.fill.holesBefore);
  CHECK(warp.filled.fill.unfilled == 0);

  size_t wallHoles = 0;
  double colorError = 0.0;
  float reddest = 0.0f;
  for (size_t i = 0; i < raw.hole.size(); ++i) {
    if (!raw.hole[i]) {
      // Known pixels are never changed.
      CHECK(filled.color.pixels[i] == raw.color.pixels[i]);
      CHECK(filled.distance.pixels[i] == raw.distance.pixels[i]);
      continue;
    }
    CHECK(!filled.hole[i]);
    // The truth behind a disocclusion is the wall (a few border pixels may
    // be the pillar's silhouette, whose triangles the stretch test dropped).
    if (warp.truth.color.pixels[i] == kPillarColor) continue;
    ++wallHoles;
    colorError += glm::length(filled.color.pixels[i] - warp.truth.color.pixels[i]);
    reddest = std::max(reddest, filled.color.pixels[i].r);
    CHECK(filled.distance.pixels[i] > 0.8f * warp.truth.distance.pixels[i]);
  }
  REQUIRE(wallHoles > 100);
  INFO("mean colour error " << colorError / double(wallHoles) << ", reddest filled pixel " << reddest);
  // The wall's colours vary smoothly; the pillar's red never reaches the fill.
  CHECK(colorError / double(wallHoles) < 0.05);
  CHECK(reddest < 0.2f);

  // Without the background preference (every surface counts: plain
  // push-pull), the pillar's red bleeds into the same holes.
  const PillarWarp plain = warpPastPillar(1e9f);
  float plainReddest = 0.0f;
  for (size_t i = 0; i < raw.hole.size(); ++i) {
    if (raw.hole[i] && warp.truth.color.pixels[i] != kPillarColor) {
      plainReddest = std::max(plainReddest, plain.filled.blended.color.pixels[i].r);
    }
  }
  CHECK(plainReddest > 0.3f);
}

TEST_CASE("a frame without holes is unchanged by the fill, and one with nothing known stays unfilled") {
  BlendedView view{ColorImage(5, 3), ScalarImage(5, 3, 2.0f), std::vector<uint8_t>(15, 0), std::vector<uint8_t>(15, 1)};
  for (size_t i = 0; i < 15; ++i) view.color.pixels[i] = glm::vec3(0.1f * float(i), 0.5f, 0.2f);
  const BlendedView before = view;
  const HoleFillStatistics none = fillHoles(view, 0.05f);
  CHECK(none.holesBefore == 0);
  CHECK(none.unfilled == 0);
  CHECK(view.color.pixels == before.color.pixels);
  CHECK(view.distance.pixels == before.distance.pixels);

  std::fill(view.hole.begin(), view.hole.end(), uint8_t(1));
  const HoleFillStatistics all = fillHoles(view, 0.05f);
  CHECK(all.holesBefore == 15);
  CHECK(all.unfilled == 15);
  CHECK(std::all_of(view.hole.begin(), view.hole.end(), [](uint8_t h) { return h == 1; }));
}

TEST_CASE("the fill takes the farthest surface, and sky counts as farthest") {
  // One hole between a near pixel (1 m, white) and a far one (4 m, grey),
  // then the same with sky (+inf, blue) as the far side.
  for (const float far : {4.0f, INFINITY}) {
    BlendedView view{ColorImage(3, 1), ScalarImage(3, 1, 0.0f), {0, 1, 0}, {1, 0, 1}};
    view.color.pixels = {glm::vec3(1.0f), glm::vec3(0.0f), glm::vec3(0.2f, 0.3f, 0.9f)};
    view.distance.pixels = {1.0f, 0.0f, far};
    const HoleFillStatistics statistics = fillHoles(view, 0.05f);
    CHECK(statistics.holesBefore == 1);
    CHECK(statistics.unfilled == 0);
    CHECK(view.color.pixels[1] == glm::vec3(0.2f, 0.3f, 0.9f));
    CHECK((std::isinf(far) ? std::isinf(view.distance.pixels[1]) : view.distance.pixels[1] == doctest::Approx(far)));
  }
}

namespace {

constexpr glm::vec3 kWallColor(0.4f, 0.45f, 0.35f), kSkyColor(0.2f, 0.3f, 0.9f), kObjectColor(1.0f);

// A 32 x 16 view of a wall 4 m away, the columns [holeBegin, holeEnd)
// holes, sky (+inf) and a near object (1 m) where the callbacks say so.
BlendedView wallView(int holeBegin, int holeEnd, bool (*sky)(int, int), bool (*object)(int, int)) {
  BlendedView view{ColorImage(32, 16), ScalarImage(32, 16, 4.0f), std::vector<uint8_t>(512, 0),
                   std::vector<uint8_t>(512, 1)};
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 32; ++x) {
      const size_t i = size_t(y) * 32 + size_t(x);
      view.color.pixels[i] = kWallColor;
      if (sky(x, y)) {
        view.color.pixels[i] = kSkyColor;
        view.distance.pixels[i] = INFINITY;
      }
      if (object(x, y)) {
        view.color.pixels[i] = kObjectColor;
        view.distance.pixels[i] = 1.0f;
      }
      if (x >= holeBegin && x < holeEnd) {
        view.hole[i] = 1;
        view.color.pixels[i] = glm::vec3(0.0f);
        view.distance.pixels[i] = 0.0f;
      }
    }
  }
  return view;
}

}  // namespace

TEST_CASE("sky seen through a small opening does not spread into a hole on the wall around it") {
  // A 2 x 2 opening onto the sky, two pixels from a hole 16 columns wide:
  // taken as the farthest surface at every coarser level, its sky would
  // fill part of the hole (as it filled a wall on oacmpdm3).
  BlendedView view = wallView(
      8, 24, [](int x, int y) { return x >= 4 && x <= 5 && y >= 6 && y <= 7; }, [](int, int) { return false; });
  const std::vector<uint8_t> holes = view.hole;
  const HoleFillStatistics statistics = fillHoles(view, 0.05f);
  CHECK(statistics.holesBefore == 256);
  CHECK(statistics.unfilled == 0);
  for (size_t i = 0; i < holes.size(); ++i) {
    if (!holes[i]) continue;
    INFO("pixel " << i % 32 << ", " << i / 32);
    CHECK(glm::length(view.color.pixels[i] - kWallColor) < 1e-5f);
    CHECK(view.distance.pixels[i] == doctest::Approx(4.0f));
  }
}

TEST_CASE("a hole between a near object and open sky is filled with the sky") {
  // The disocclusion beside an object seen against the sky: sky is the
  // farthest surface, and here not outnumbered.
  BlendedView view = wallView(
      12, 20, [](int x, int) { return x >= 20; }, [](int x, int) { return x < 12; });
  const std::vector<uint8_t> holes = view.hole;
  const HoleFillStatistics statistics = fillHoles(view, 0.05f);
  CHECK(statistics.holesBefore == 128);
  for (size_t i = 0; i < holes.size(); ++i) {
    if (!holes[i]) continue;
    INFO("pixel " << i % 32 << ", " << i / 32);
    INFO("colour " << view.color.pixels[i].r << " " << view.color.pixels[i].g << " " << view.color.pixels[i].b);
    CHECK(glm::length(view.color.pixels[i] - kSkyColor) < 1e-5f);
    CHECK(std::isinf(view.distance.pixels[i]));
  }
}

TEST_CASE("hole modes parse by name and refuse anything else") {
  CHECK(parseHoleMode("fill") == HoleMode::Fill);
  CHECK(parseHoleMode("mark") == HoleMode::Mark);
  CHECK(parseHoleMode("black") == HoleMode::Black);
  CHECK_THROWS_WITH_AS(parseHoleMode("blur"), doctest::Contains("unknown hole mode 'blur'"), InputError);
}

TEST_CASE("the fill is the same for any thread count") {
  const PillarWarp warp = warpPastPillar(BlendOptions{}.epsilon);
  BlendedView single = warp.raw.blended, parallel = warp.raw.blended;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    fillHoles(single, BlendOptions{}.epsilon);
  }
  fillHoles(parallel, BlendOptions{}.epsilon);
  CHECK(single.color.pixels == parallel.color.pixels);
  CHECK(single.distance.pixels == parallel.distance.pixels);
  CHECK(single.hole == parallel.hole);
}

}  // namespace triwalk
