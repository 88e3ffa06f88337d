// The CPU reference warp, blend and error against scenes with known answers.

#include "core/synthesis/warp.h"
#include "core/image/color.h"
#include "core/synthesis/blend.h"
#include "core/synthesis/reconstruction_error.h"
#include "core/synthesis/view_synthesis.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <tbb/global_control.h>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

namespace triwalk {

using testing::AnalyticScene;
using testing::renderPanorama;

namespace {

constexpr int kWidth = 256;

AnalyticScene roomWithPillar() {
  AnalyticScene scene;
  scene.room = AnalyticScene::Room{{-5.0f, -1.0f, 0.0f}, {5.0f, 4.0f, 3.0f}, false};
  scene.cylinders.push_back({{0.0f, 2.0f}, 0.3f, 0.0f, 3.0f});
  return scene;
}

ReconstructionError compare(const BlendedView& view, const Panorama& truth, ScalarImage* perPixel = nullptr) {
  return reconstructionError(toDisplayColors(view.color), view.hole, toDisplayColors(truth.color), ErrorOptions{}, perPixel);
}

// The warp and blend without the hole fill: these tests look at what the
// warp itself leaves.
const SynthesisOptions kRaw{.warp = {}, .blend = {}, .holes = HoleMode::Mark};

// A source in roomWithPillar(), its panorama simplified or not.
std::unique_ptr<WarpSource> pillarRoomSource(SourceMesh mesh) {
  const glm::vec3 position(-1.0f, 0.0f, 1.5f);
  WarpOptions options;
  options.mesh = mesh;
  return std::make_unique<WarpSource>(renderPanorama(roomWithPillar(), position, kWidth), position, 0.0f, options);
}

SynthesizedView synthesize(const AnalyticScene& scene, std::vector<glm::vec3> sourcePositions, glm::vec3 destination,
                           const SynthesisOptions& options = kRaw) {
  std::vector<std::unique_ptr<WarpSource>> sources;
  std::vector<const WarpSource*> pointers;
  for (glm::vec3 position : sourcePositions) {
    sources.push_back(std::make_unique<WarpSource>(renderPanorama(scene, position, kWidth), position, 0.0f, options.warp));
    pointers.push_back(sources.back().get());
  }
  return synthesizeView(pointers, DestinationCamera::panorama(destination, kWidth, kWidth / 2), options);
}

}  // namespace

TEST_CASE("a source warped to its own position reproduces itself exactly") {
  const AnalyticScene scene = roomWithPillar();
  const glm::vec3 position(-1.0f, 0.0f, 1.5f);
  const Panorama truth = renderPanorama(scene, position, kWidth);
  const SynthesizedView view = synthesize(scene, {position}, position);
  const ReconstructionError error = compare(view.blended, truth);
  CHECK(error.rms < 1e-6);
  CHECK(error.badPercent == 0.0);
  CHECK(error.total < 1e-5);
  CHECK(std::count(view.blended.hole.begin(), view.blended.hole.end(), uint8_t(1)) == 0);
}

TEST_CASE("box scene warped to a new position matches the view rendered there") {
  // Inside a closed room nothing is hidden: the warp must reproduce the
  // destination up to interpolation of a pattern that is smooth in space
  // (continuous across the room's edges).
  AnalyticScene scene;
  scene.room = AnalyticScene::Room{{-3.0f, -2.0f, 0.0f}, {3.0f, 2.0f, 2.5f}, false};
  scene.shade = [](glm::vec3 p, int) { return testing::smoothPattern(p, 0); };
  const glm::vec3 source(0.0f, 0.0f, 1.5f), destination(0.4f, -0.3f, 1.2f);
  const SynthesizedView view = synthesize(scene, {source}, destination);
  const ReconstructionError error = compare(view.blended, renderPanorama(scene, destination, kWidth));
  INFO("R " << error.rms << " B " << error.badPercent);
  CHECK(error.rms < 0.01);
  CHECK(error.badPercent < 0.5);
  // The distance channel too: within 0.5% except along the room's edges,
  // where a triangle spanning two walls cuts the corner (a chord).
  const Panorama truth = renderPanorama(scene, destination, kWidth);
  const EquirectProjection projection{kWidth, kWidth / 2, 0.0f};
  float worst = 0.0f, worstAwayFromEdges = 0.0f;
  for (int v = 0; v < kWidth / 2; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const float relative = std::abs(view.blended.distance.at(u, v) - truth.distance.at(u, v)) / truth.distance.at(u, v);
      worst = std::max(worst, relative);
      bool nearEdge = false;
      const int surface = scene.trace(destination, projection.pixelDirection(u, v)).surface;
      for (int dv = -2; dv <= 2; ++dv) {
        for (int du = -2; du <= 2; ++du) {
          const int nv = std::clamp(v + dv, 0, kWidth / 2 - 1), nu = (u + du + kWidth) % kWidth;
          nearEdge |= scene.trace(destination, projection.pixelDirection(nu, nv)).surface != surface;
        }
      }
      if (!nearEdge) worstAwayFromEdges = std::max(worstAwayFromEdges, relative);
    }
  }
  CHECK(worst < 0.03f);
  CHECK(worstAwayFromEdges < 0.005f);
}

TEST_CASE("plane with sky warped to a new position matches where the plane is not seen edge-on") {
  AnalyticScene scene;
  scene.boxes.push_back({{-4.0f, -4.0f, -0.1f}, {4.0f, 4.0f, 0.0f}});  // a floor slab under open sky
  scene.shade = [](glm::vec3 p, int) { return testing::smoothPattern(p, 0); };
  const glm::vec3 source(0.0f, 0.0f, 1.6f), destination(0.5f, 0.3f, 1.6f);
  const SynthesizedView view = synthesize(scene, {source}, destination);
  const Panorama truth = renderPanorama(scene, destination, kWidth);
  // Compare the sky and the floor nearer than 5 m (at eye height 1.6 m the
  // floor is seen at more than 18 degrees there), away from the slab's
  // silhouette against the sky, which no triangle spans.
  size_t compared = 0, bad = 0;
  for (size_t i = 0; i < truth.color.pixelCount(); ++i) {
    const int u = int(i % kWidth), v = int(i / kWidth);
    bool silhouette = false;
    for (int dv = -1; dv <= 1; ++dv) {
      for (int du = -1; du <= 1; ++du) {
        const int nv = std::clamp(v + dv, 0, kWidth / 2 - 1), nu = (u + du + kWidth) % kWidth;
        silhouette |= std::isinf(truth.distance.at(nu, nv)) != std::isinf(truth.distance.pixels[i]);
      }
    }
    const float d = truth.distance.pixels[i];
    if (silhouette || !(std::isinf(d) || d < 5.0f)) continue;
    ++compared;
    const glm::vec3 difference = glm::abs(displayColor(view.blended.color.pixels[i]) - displayColor(truth.color.pixels[i]));
    bad += view.blended.hole[i] || std::max({difference.r, difference.g, difference.b}) > 15.0f / 255.0f;
  }
  CHECK(compared > truth.color.pixelCount() * 3 / 4);
  CHECK(bad <= compared / 200);
}

TEST_CASE("a pillar leaves a hole exactly where the wall is hidden from the source, and a second source fills it") {
  //   y=4  ==========  back wall  ==========
  //                      region R: seen from D, hidden from S1 by the pillar
  //   y=2               ( pillar r=0.3 at x=0 )
  //   y=0      S1 (-1)              D (1)     S2 (2)
  const AnalyticScene scene = roomWithPillar();
  const glm::vec3 s1(-1.0f, 0.0f, 1.5f), destination(1.0f, 0.0f, 1.5f), s2(2.0f, 0.0f, 1.5f);
  const EquirectProjection projection{kWidth, kWidth / 2, 0.0f};
  const SynthesizedView fromS1 = synthesize(scene, {s1}, destination);
  const SynthesizedView fromBoth = synthesize(scene, {s1, s2}, destination);

  size_t hiddenPixels = 0, mismatches = 0, filled = 0;
  for (int v = 0; v < projection.height; ++v) {
    for (int u = 0; u < projection.width; ++u) {
      const testing::AnalyticHit hit = scene.trace(destination, projection.pixelDirection(u, v));
      if (hit.surface != 3) continue;  // the back wall, y = 4
      const glm::vec3 point = destination + hit.distance * projection.pixelDirection(u, v);
      const testing::AnalyticHit fromSource = scene.trace(s1, glm::normalize(point - s1));
      const bool hidden = fromSource.surface != 3;
      // Decide only away from the region's boundary: the neighbours agree.
      bool boundary = false;
      for (int du = -2; du <= 2; ++du) {
        const glm::vec3 direction = projection.pixelDirection((u + du + kWidth) % kWidth, v);
        const testing::AnalyticHit neighbour = scene.trace(destination, direction);
        if (neighbour.surface != 3) { boundary = true; continue; }
        const glm::vec3 p = destination + neighbour.distance * direction;
        boundary |= (scene.trace(s1, glm::normalize(p - s1)).surface != 3) != hidden;
      }
      if (boundary) continue;
      const size_t i = size_t(v) * size_t(kWidth) + size_t(u);
      hiddenPixels += hidden;
      mismatches += bool(fromS1.blended.hole[i]) != hidden;
      filled += hidden && !fromBoth.blended.hole[i];
    }
  }
  INFO("hidden " << hiddenPixels << " mismatches " << mismatches << " filled " << filled);
  CHECK(hiddenPixels > 100);
  CHECK(mismatches == 0);
  CHECK(filled == hiddenPixels);
}

TEST_CASE("triangles crossing the destination seam are split, not smeared across the panorama") {
  // A red stripe on the west wall straight behind the destination's seam
  // (longitude -180 degrees); the source sits slightly beside it.
  AnalyticScene scene;
  scene.room = AnalyticScene::Room{{-4.0f, -3.0f, 0.0f}, {4.0f, 3.0f, 3.0f}, false};
  scene.shade = [](glm::vec3 p, int surface) {
    if (surface == 0 && std::abs(p.y - 0.2f) < 0.3f) return glm::vec3(0.9f, 0.02f, 0.02f);
    return glm::vec3(0.2f, 0.5f, 0.3f);
  };
  const glm::vec3 source(0.3f, -0.1f, 1.5f), destination(0.0f, 0.2f, 1.5f);
  const SynthesizedView view = synthesize(scene, {source}, destination);
  const Panorama truth = renderPanorama(scene, destination, kWidth);
  size_t redAwayFromSeam = 0, seamHoles = 0, seamWrong = 0;
  for (int v = 8; v < kWidth / 2 - 8; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const size_t i = size_t(v) * size_t(kWidth) + size_t(u);
      const bool nearSeam = u < 16 || u >= kWidth - 16;
      const bool red = view.blended.color.pixels[i].r > 0.5f;
      if (!nearSeam) redAwayFromSeam += red;
      if (u == 0 || u == kWidth - 1) {
        seamHoles += view.blended.hole[i];
        seamWrong += red != (truth.color.pixels[i].r > 0.5f);
      }
    }
  }
  CHECK(redAwayFromSeam == 0);
  CHECK(seamHoles == 0);
  CHECK(seamWrong <= 4);  // at the stripe's edges only
}

TEST_CASE("the paper's point warp leaves cracks where the mesh warp does not") {
  AnalyticScene scene;
  scene.room = AnalyticScene::Room{{-3.0f, -2.0f, 0.0f}, {3.0f, 2.0f, 2.5f}, false};
  const glm::vec3 source(-1.0f, 0.0f, 1.5f), destination(1.5f, 0.0f, 1.5f);  // magnifies the east wall
  SynthesisOptions point = kRaw;
  point.warp.method = WarpMethod::Point;
  const SynthesizedView mesh = synthesize(scene, {source}, destination);
  const SynthesizedView points = synthesize(scene, {source}, destination, point);
  const auto holes = [](const SynthesizedView& view) {
    return double(std::count(view.blended.hole.begin(), view.blended.hole.end(), uint8_t(1))) / double(view.blended.hole.size());
  };
  CHECK(holes(mesh) == 0.0);
  CHECK(holes(points) > 0.05);
}

TEST_CASE("the stretch test drops rubber sheets: without it they hide what a second source sees") {
  const AnalyticScene scene = roomWithPillar();
  const glm::vec3 s1(-1.0f, 0.0f, 1.5f), destination(1.0f, 0.0f, 1.5f), s2(2.0f, 0.0f, 1.5f);
  const Panorama truth = renderPanorama(scene, destination, kWidth);
  SynthesisOptions none = kRaw;
  none.warp.stretchTest = StretchTest::None;
  SynthesisOptions ratio = kRaw;
  ratio.warp.stretchTest = StretchTest::DepthRatio;
  const ReconstructionError withGrazing = compare(synthesize(scene, {s1, s2}, destination).blended, truth);
  const ReconstructionError withRatio = compare(synthesize(scene, {s1, s2}, destination, ratio).blended, truth);
  const ReconstructionError without = compare(synthesize(scene, {s1, s2}, destination, none).blended, truth);
  INFO("E grazing " << withGrazing.total << " ratio " << withRatio.total << " none " << without.total);
  CHECK(withGrazing.total < 0.5 * without.total);
  CHECK(withRatio.total < 0.5 * without.total);
}

TEST_CASE("warp results are identical for any thread count") {
  const std::unique_ptr<WarpSource> source = pillarRoomSource(SourceMesh::Grid);
  const DestinationCamera camera = DestinationCamera::panorama(glm::vec3(1.0f, 0.3f, 1.4f), kWidth, kWidth / 2);
  const WarpLayer all = warpToCamera(*source, camera, WarpMethod::Mesh);
  WarpLayer one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = warpToCamera(*source, camera, WarpMethod::Mesh);
  }
  CHECK(one.color.pixels == all.color.pixels);
  CHECK(one.distance.pixels == all.distance.pixels);
  CHECK(one.covered == all.covered);
}

TEST_CASE("row spans and the row loop warp to the same layer as the per-pixel test of each range, testing a fraction of it") {
  // The room's walls, floor and ceiling simplify to triangles tens of
  // columns wide, some around a pole or across the seam; a yawed
  // destination moves the seam through them. The plain scan tests every
  // pixel of each triangle's range with the resolve's own coverage test,
  // so this also holds the row loop (SphericalTriangle::scanRow) to it:
  // a loop that rejects a pixel the test accepts changes the layer, one
  // that accepts a pixel it rejects fails the resolve.
  for (const SourceMesh mesh : {SourceMesh::Simplified, SourceMesh::Grid}) {
    const std::unique_ptr<WarpSource> source = pillarRoomSource(mesh);
    for (const float yaw : {0.0f, 1.3f, -2.9f}) {
      for (const glm::vec3 destination : {glm::vec3(1.0f, 0.3f, 1.4f), glm::vec3(-3.5f, 3.2f, 2.6f)}) {
        const DestinationCamera camera = DestinationCamera::panorama(destination, kWidth, kWidth / 2, yaw);
        const WarpLayer spans = warpToCamera(*source, camera, WarpMethod::Mesh, LayerReliability::Computed);
        const WarpLayer scanned =
            warpToCamera(*source, camera, WarpMethod::Mesh, LayerReliability::Computed, PanoramaRaster::BoundingBox);
        INFO(sourceMeshName(mesh) << " yaw " << yaw << " destination " << destination.x << ", " << destination.y);
        CHECK(spans.covered == scanned.covered);
        CHECK(spans.distance.pixels == scanned.distance.pixels);
        CHECK(spans.color.pixels == scanned.color.pixels);
        CHECK(spans.reliability == scanned.reliability);
        INFO("pixel centres tested: " << spans.pixelsTested << " with spans, " << scanned.pixelsTested << " without");
        if (mesh == SourceMesh::Simplified) {
          CHECK(3 * spans.pixelsTested < 2 * scanned.pixelsTested);
        } else {
          CHECK(spans.pixelsTested <= scanned.pixelsTested);
        }
      }
    }
  }
}

TEST_CASE("a panorama's lattice warps to exactly the whole panorama's pixels there, testing a fraction of them") {
  // Every stride-th row and column: the same pixel centres, the same
  // coverage tests and z-test, so the same bits, whatever the source mesh,
  // the warp method, the seam's place (yaw) or the destination.
  for (const SourceMesh mesh : {SourceMesh::Simplified, SourceMesh::Grid}) {
    const std::unique_ptr<WarpSource> source = pillarRoomSource(mesh);
    for (const WarpMethod method : {WarpMethod::Mesh, WarpMethod::Point}) {
      for (const float yaw : {0.0f, -2.9f}) {
        for (const glm::vec3 destination : {glm::vec3(1.0f, 0.3f, 1.4f), glm::vec3(-3.5f, 3.2f, 2.6f)}) {
          const WarpLayer whole = warpToCamera(*source, DestinationCamera::panorama(destination, kWidth, kWidth / 2, yaw),
                                               method, LayerReliability::Computed);
          for (const int stride : {2, 4}) {
            INFO(sourceMeshName(mesh) << (method == WarpMethod::Mesh ? " mesh" : " point") << " warp, yaw " << yaw
                                      << ", destination " << destination.x << ", " << destination.y << ", stride " << stride);
            const DestinationCamera camera = DestinationCamera::panoramaLattice(destination, kWidth, kWidth / 2, stride, yaw);
            const WarpLayer lattice = warpToCamera(*source, camera, method, LayerReliability::Computed);
            REQUIRE(lattice.color.width == kWidth / stride);
            REQUIRE(lattice.color.height == kWidth / 2 / stride);
            size_t mismatches = 0, covered = 0;
            for (int y = 0; y < lattice.color.height; ++y) {
              for (int x = 0; x < lattice.color.width; ++x) {
                const size_t i = size_t(y) * size_t(lattice.color.width) + size_t(x);
                const size_t j = size_t(y * stride) * size_t(kWidth) + size_t(x * stride);
                covered += lattice.covered[i];
                const bool same = lattice.covered[i] == whole.covered[j] &&
                                  testing::sameBits(lattice.distance.pixels[i], whole.distance.pixels[j]) &&
                                  lattice.color.pixels[i] == whole.color.pixels[j] &&
                                  lattice.reliability[i] == whole.reliability[j];
                mismatches += same ? 0 : 1;
              }
            }
            CHECK(mismatches == 0);
            if (method == WarpMethod::Mesh) {
              CHECK(covered > lattice.covered.size() / 2);
              INFO("pixel centres tested: " << lattice.pixelsTested << " on the lattice, " << whole.pixelsTested << " in all");
              CHECK(lattice.pixelsTested * size_t(stride) < whole.pixelsTested);
            }
          }
        }
      }
    }
  }
}

TEST_CASE("a simplified source numbers grid triangles as its own vertices, and refuses vertices it does not have") {
  const std::unique_ptr<WarpSource> source = pillarRoomSource(SourceMesh::Simplified);
  const SimplifiedTriangles& grid = source->simplifiedTriangles();
  REQUIRE(grid.surface.size() + grid.sky.size() == 3 * size_t(source->triangleCount()));
  const std::optional<std::vector<uint32_t>> mine = source->sourceTriangles(grid);
  REQUIRE(mine);
  REQUIRE(mine->size() == 3 * size_t(source->triangleCount()));
  // The source's own triangles, surface then sky, are the same vertices.
  for (uint32_t t = 0; t < source->triangleCount(); ++t) {
    uint32_t v[3];
    source->triangleVertices(t, v);
    for (int k = 0; k < 3; ++k) CHECK((*mine)[3 * t + k] == v[k]);
  }
  // A pixel no simplified triangle uses (the first, in the top row, where
  // the source looks straight up at the ceiling: no orphan either), and a
  // number past the grid's pixels and poles.
  std::vector<uint8_t> used(size_t(kWidth) * size_t(kWidth / 2) + 2, 0);
  for (const std::vector<uint32_t>* list : {&grid.surface, &grid.sky}) {
    for (const uint32_t v : *list) used[v] = 1;
  }
  const auto unused = std::find(used.begin(), used.end(), uint8_t(0));
  REQUIRE(unused != used.end());
  for (const uint32_t foreign : {uint32_t(unused - used.begin()), uint32_t(used.size())}) {
    SimplifiedTriangles other = grid;
    other.surface[1] = foreign;
    CHECK_FALSE(source->sourceTriangles(other));
  }
}

TEST_CASE("blend: nearest layer wins, layers within epsilon average with inverse-distance weights") {
  // Three one-pixel layers: A at 2.0 m, B at 2.05 m (within 5% of A), C at 3 m (behind).
  auto layer = [](glm::vec3 color, float distance) {
    WarpLayer l{ColorImage(1, 1, color), ScalarImage(1, 1, distance), {1}, 0, 0, {}, {}};
    return l;
  };
  const std::vector<WarpLayer> layers = {layer({1, 0, 0}, 2.0f), layer({0, 1, 0}, 2.05f), layer({0, 0, 1}, 3.0f)};
  const glm::vec3 positions[3] = {{1, 0, 0}, {0, 4, 0}, {0, 0, 0.5f}};
  const std::vector<float> weights = blendWeights(glm::vec3(0.0f), positions, BlendOptions{});
  CHECK(weights[0] == doctest::Approx(1.0));
  CHECK(weights[1] == doctest::Approx(0.25));
  const std::vector<const WarpLayer*> pointers = {&layers[0], &layers[1], &layers[2]};
  const BlendedView view = blendLayers(pointers, weights, BlendOptions{});
  CHECK(view.color.pixels[0].r == doctest::Approx(0.8));  // 1 / (1 + 0.25)
  CHECK(view.color.pixels[0].g == doctest::Approx(0.2));
  CHECK(view.color.pixels[0].b == doctest::Approx(0.0));
  CHECK(view.distance.pixels[0] == doctest::Approx(2.0));
  CHECK(view.contributors[0] == 0b011);
  BlendOptions narrow;
  narrow.epsilon = 0.01f;
  CHECK(blendLayers(pointers, weights, narrow).color.pixels[0] == glm::vec3(1, 0, 0));
}

TEST_CASE("R, B and E by hand on a 4x2 image") {
  // Truth: gray 0.5 everywhere (display values). Reconstruction: pixel 0 off
  // by 0.1 in every channel, pixel 1 off by 0.2 in red, pixel 2 a hole
  // (black: off by 0.5 in every channel), the rest exact.
  //   R = sqrt((3*0.01 + 0.04 + 3*0.25) / (3*8)) = sqrt(0.82 / 24) = 0.1848422
  //   B = 3 bad of 8 = 37.5 %  (0.1 and 0.2 exceed 15/255 = 0.0588; holes are bad)
  //   E = 10 R + 0.1 B = 1.848422 + 3.75 = 5.598422
  const ColorImage truth(4, 2, glm::vec3(0.5f));
  ColorImage reconstruction = truth;
  reconstruction.pixels[0] = glm::vec3(0.6f);
  reconstruction.pixels[1] = glm::vec3(0.7f, 0.5f, 0.5f);
  std::vector<uint8_t> hole(8, 0);
  hole[2] = 1;
  ErrorOptions uniform;
  uniform.weighting = PixelWeighting::Uniform;
  ScalarImage perPixel;
  const ReconstructionError error = reconstructionError(reconstruction, hole, truth, uniform, &perPixel);
  CHECK(error.rms == doctest::Approx(0.1848422).epsilon(1e-6));
  CHECK(error.badPercent == doctest::Approx(37.5));
  CHECK(error.total == doctest::Approx(5.598422).epsilon(1e-6));
  CHECK(perPixel.pixels[2] == 1.0f);
  CHECK(perPixel.pixels[0] == doctest::Approx(0.1));

  // Solid-angle weighting on a 2x4 panorama: rows at latitudes 67.5, 22.5,
  // -22.5, -67.5 degrees weigh cos(67.5) = 0.382683 and cos(22.5) = 0.923880.
  // One bad pixel (0.2 in every channel) in the top row:
  //   B = 100 * 0.382683 / (2 * 2 * (0.382683 + 0.923880)) = 7.322329 %
  //   R = sqrt(0.382683 * 3 * 0.04 / (3 * 2 * 2 * 1.306563)) = 0.0541196
  //   E = 0.541196 + 0.7322329 = 1.273429
  const ColorImage panoramaTruth(2, 4, glm::vec3(0.5f));
  ColorImage panoramaReconstruction = panoramaTruth;
  panoramaReconstruction.pixels[0] = glm::vec3(0.7f);
  const ReconstructionError weighted = reconstructionError(panoramaReconstruction, {}, panoramaTruth, ErrorOptions{});
  CHECK(weighted.badPercent == doctest::Approx(7.322329).epsilon(1e-5));
  CHECK(weighted.rms == doctest::Approx(0.0541196).epsilon(1e-5));
  CHECK(weighted.total == doctest::Approx(1.273429).epsilon(1e-5));
}

TEST_CASE("an error on a lattice: its rows weighted by their own latitudes, normalised over its pixels") {
  // An 8x4 panorama, stride 2: rows 0 and 2 (latitudes 67.5 and -22.5
  // degrees, weights 0.382683 and 0.923880), columns 0, 2, 4 and 6. One bad
  // pixel on the lattice, at (2, 2), off by 0.2 in every channel:
  //   B = 100 * 0.923880 / (4 * (0.382683 + 0.923880)) = 17.677670 %
  //   R = sqrt(0.923880 * 3 * 0.04 / (3 * 4 * 1.306563)) = 0.0840896
  //   E = 0.840896 + 1.7677670 = 2.608663
  // (the whole image's rows 1 and 3 weigh nothing here).
  const glm::vec3 gray(0.5f), bad(0.7f);
  ErrorAccumulator lattice(8, 4, ErrorOptions{}, 2);
  for (int y = 0; y < 4; y += 2) {
    for (int x = 0; x < 8; x += 2) lattice.add(y, x == 2 && y == 2 ? bad : gray, false, gray);
  }
  const ReconstructionError error = lattice.result();
  CHECK(error.badPercent == doctest::Approx(17.677670).epsilon(1e-6));
  CHECK(error.rms == doctest::Approx(0.0840896).epsilon(1e-6));
  CHECK(error.total == doctest::Approx(2.608663).epsilon(1e-6));

  // A difference the same everywhere is the same error on any lattice.
  const ColorImage off(8, 4, glm::vec3(0.6f));
  const ReconstructionError everywhere = reconstructionError(off, {}, ColorImage(8, 4, gray), ErrorOptions{});
  for (const int stride : {2, 4}) {
    ErrorAccumulator sparse(8, 4, ErrorOptions{}, stride);
    for (int y = 0; y < 4; y += stride) {
      for (int x = 0; x < 8; x += stride) sparse.add(y, glm::vec3(0.6f), false, gray);
    }
    CHECK(sparse.result().rms == doctest::Approx(everywhere.rms).epsilon(1e-12));
    CHECK(sparse.result().badPercent == doctest::Approx(everywhere.badPercent).epsilon(1e-12));
  }
}

}  // namespace triwalk
