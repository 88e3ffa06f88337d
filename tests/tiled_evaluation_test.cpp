// Table 1 by tiles equals Table 1 over the whole data set, number for
// number: on the wall-and-clutter room, cut into cores of at most 16 samples,
// for a dense mesh, a sparse one whose long triangles reach across cores,
// and both triangle destination rules that read one and several samples.

#include "core/io/dataset.h"
#include "core/selection/baselines.h"
#include "core/selection/evaluation.h"
#include "core/selection/selection.h"
#include "core/selection/tile_partition.h"
#include "core/selection/tiled_evaluation.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

namespace triwalk {

TEST_CASE("eval by tiles gives the same triangle and probe errors as eval over every view at once") {
  testing::TemporaryDirectory directory;
  testing::writeWallAndClutterDataset(directory / "data", 16, 6, 32, 24);  // 96 samples over 8 x 3 m
  const Dataset dataset = Dataset::open(directory / "data");
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  const ViewMesh dense = datasetMesh(dataset, {}, "dense");
  const ViewMesh sparse = datasetMesh(dataset, kMedoidsSelection(positions, 9), "sparse");
  constexpr size_t kMostTileSamples = 16;
  REQUIRE(splitIntoCores(positions, 0.0, {.mostTileSamples = kMostTileSamples}).size() >= 5);

  for (TriangleDestinations destinations : {TriangleDestinations::Centroid, TriangleDestinations::Quadrature}) {
    CAPTURE(triangleDestinationsName(destinations));
    TriangleErrorSettings settings;
    settings.width = 32;
    settings.destinations = destinations;
    DatasetTriangleErrors whole(dataset, settings, LoadedViews::SamplesAndProbes, true);
    const std::vector<MethodEvaluation> tiled =
        evaluateMeshesInTiles(dataset, {{"dense", &dense}, {"sparse", &sparse}}, settings, kMostTileSamples, true);
    REQUIRE(tiled.size() == 2);
    for (const auto& [mesh, byTiles] : {std::pair{&dense, tiled[0]}, std::pair{&sparse, tiled[1]}}) {
      const MethodEvaluation once = evaluateMesh(byTiles.method, *mesh, whole);
      CHECK(byTiles.samples == once.samples);
      CHECK(byTiles.triangles == once.triangles);
      CHECK(byTiles.triangleErrors == once.triangleErrors);  // exactly: the same reconstructions, summed alike
      CHECK(byTiles.probeErrors == once.probeErrors);
      CHECK(byTiles.probeTriangles == once.probeTriangles);
      CHECK(byTiles.meanError == once.meanError);
      CHECK(byTiles.probeMeanError == once.probeMeanError);
    }
  }
}

}  // namespace triwalk
