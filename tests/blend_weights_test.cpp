// The blend's reliability weights (core/synthesis/warp_reliability.h): the
// formula on cases worked by hand, the CPU warp's per-pixel values against
// the analytic answer, and the blend on a scene where one reference saw a
// surface obliquely and another face-on.

#include "core/synthesis/blend.h"
#include "core/synthesis/reconstruction_error.h"
#include "core/synthesis/view_synthesis.h"
#include "core/synthesis/warp_reliability.h"
#include "tests/analytic_scene.h"

#include <doctest/doctest.h>

#include <cmath>

namespace triwalk {

TEST_CASE("reliability: the source's solid angle over the destination's, capped at 1") {
  const glm::vec3 point(0.0f), normal(0.0f, 0.0f, 2.0f);  // the normal's length does not matter
  // Face-on from 2 m and from 1 m: the destination sees the patch 4 times larger.
  CHECK(warpReliability(point, normal, {0, 0, 2}, {0, 0, 1}) == doctest::Approx(0.25));
  // The other way round the source saw it in more detail than needed: 1.
  CHECK(warpReliability(point, normal, {0, 0, 1}, {0, 0, 2}) == 1.0f);
  // Same distance, the source 60 degrees off the normal: cos 60 / cos 0.
  const float s = std::sqrt(3.0f) / 2.0f;
  CHECK(warpReliability(point, normal, {0, s * 2.0f, 1.0f}, {0, 0, 2}) == doctest::Approx(0.5));
  // Grazing from the source: floored, never zero.
  CHECK(warpReliability(point, normal, {0, 2, 0}, {0, 0, 2}) == kMinimumReliability);
  // Edge-on from the destination, or no normal (a splatted point): 1.
  CHECK(warpReliability(point, normal, {0, 0, 2}, {0, 2, 0}) == 1.0f);
  CHECK(warpReliability(point, glm::vec3(0.0f), {0, 0, 2}, {0, 0, 1}) == 1.0f);
}

TEST_CASE("the warp's reliability of a wall seen face-on from half the distance is a quarter") {
  // The wall x = 5 seen straight ahead from (1, 0, 1.5) (4 m) and warped to
  // (3, 0, 1.5) (2 m): rho = (1 / 16) / (1 / 4).
  const testing::AnalyticScene scene = testing::stripedRoom();
  const int width = 256;
  const glm::vec3 reference(1.0f, 0.0f, 1.5f), destination(3.0f, 0.0f, 1.5f);
  const WarpSource source(testing::renderPanorama(scene, reference, width), reference, 0.0f, WarpOptions{});
  const WarpLayer layer = warpToCamera(source, DestinationCamera::panorama(destination, width, width / 2), WarpMethod::Mesh);
  // Pixel (W/2, H/2) looks along +x (theta = 0 at x = W/2), just below the horizon.
  const size_t ahead = size_t(width / 4) * size_t(width) + size_t(width / 2);
  REQUIRE(layer.covered[ahead] == 1);
  CHECK(layer.distance.pixels[ahead] == doctest::Approx(2.0).epsilon(0.01));
  CHECK(layer.reliabilityAt(ahead) == doctest::Approx(0.25).epsilon(0.02));
  // Looking back (-x), the wall x = -5 is 6 m from the source and 8 m from
  // the destination, which sees it smaller than the source did: 1.
  const size_t behind = size_t(width / 4) * size_t(width) + 1;
  REQUIRE(layer.covered[behind] == 1);
  CHECK(layer.reliabilityAt(behind) == 1.0f);
}

TEST_CASE("blend: within the interval each layer weighs its inverse distance times its reliability") {
  auto layer = [](glm::vec3 color, float reliability) {
    return WarpLayer{ColorImage(1, 1, color), ScalarImage(1, 1, 2.0f), {1}, 0, 0, {}, {reliability}};
  };
  const std::vector<WarpLayer> layers = {layer({1, 0, 0}, 1.0f), layer({0, 1, 0}, 0.25f)};
  const std::vector<const WarpLayer*> pointers = {&layers[0], &layers[1]};
  const std::vector<float> weights = {0.5f, 1.0f};  // the second reference is nearer
  BlendOptions options;
  CHECK(options.weights == BlendWeights::Reliability);
  // Weights 0.5 x 1 and 1 x 0.25: red 0.5 / 0.75.
  const BlendedView reliable = blendLayers(pointers, weights, options);
  CHECK(reliable.color.pixels[0].r == doctest::Approx(2.0 / 3.0));
  CHECK(reliable.color.pixels[0].g == doctest::Approx(1.0 / 3.0));
  options.weights = BlendWeights::Distance;
  const BlendedView paper = blendLayers(pointers, weights, options);
  CHECK(paper.color.pixels[0].r == doctest::Approx(1.0 / 3.0));
  CHECK(paper.color.pixels[0].g == doctest::Approx(2.0 / 3.0));
}

TEST_CASE("reliability weights reconstruct a striped wall better where one reference saw it obliquely") {
  // The destination looks at the wall y = 5 from (0, 3). Reference A stands
  // right in front of it, nearer the wall than the destination; reference B
  // is nearer the destination but sees the wall at a grazing angle, its
  // stripes sampled coarsely. The paper's weights favour B (nearer); the
  // reliability gives the wall to A.
  const testing::AnalyticScene scene = testing::stripedRoom();
  const int width = 512;
  const glm::vec3 destination(0.0f, 3.0f, 1.5f);
  const glm::vec3 positions[] = {{0.0f, 4.0f, 1.5f}, {-4.0f, 3.2f, 1.5f}};
  const WarpSource a(testing::renderPanorama(scene, positions[0], width), positions[0], 0.0f, WarpOptions{});
  const WarpSource b(testing::renderPanorama(scene, positions[1], width), positions[1], 0.0f, WarpOptions{});
  const WarpSource* sources[] = {&a, &b};
  const Panorama truth = testing::renderPanorama(scene, destination, width);
  const DestinationCamera camera = DestinationCamera::panorama(destination, width, width / 2);
  SynthesisOptions options;
  options.holes = HoleMode::Mark;
  const SynthesizedView reliable = synthesizeView(sources, camera, options);
  options.blend.weights = BlendWeights::Distance;
  const SynthesizedView paper = synthesizeView(sources, camera, options);
  const ColorImage truthDisplay = toDisplayColors(truth.color);
  const double reliableError =
      reconstructionError(toDisplayColors(reliable.blended.color), reliable.blended.hole, truthDisplay, ErrorOptions{}).total;
  const double paperError =
      reconstructionError(toDisplayColors(paper.blended.color), paper.blended.hole, truthDisplay, ErrorOptions{}).total;
  INFO("E with reliability " << reliableError << ", with inverse distance alone " << paperError);
  CHECK(reliableError < 0.8 * paperError);
}

}  // namespace triwalk
