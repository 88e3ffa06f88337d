// The selection follows the error: on a scene whose one half is bare and
// the other cluttered, the served-sample cost puts its references where
// reconstructions fail, and its estimate of a triangle's error agrees with
// held-out probes better than the paper's one destination at the centroid.

#include "core/io/dataset.h"
#include "core/selection/baselines.h"
#include "core/selection/edge_collapse_decimator.h"
#include "core/selection/evaluation.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection.h"
#include "core/selection/triangle_error.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <set>

namespace triwalk {

namespace {

// 16 paths x 6 samples, 0.53 x 0.6 m apart, over the 8 x 3 m room.
constexpr int kPaths = 16, kSteps = 6, kWidth = 64;

std::pair<int, int> countHalves(const Dataset& dataset, const std::vector<int>& samples) {
  int bare = 0, cluttered = 0;
  for (int s : samples) (dataset.sample(s).position.x < 4.0f ? bare : cluttered) += 1;
  return {bare, cluttered};
}

std::vector<double> ranks(const std::vector<double>& values) {
  std::vector<size_t> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a] < values[b]; });
  std::vector<double> rank(values.size());
  for (size_t i = 0; i < order.size(); ++i) rank[order[i]] = double(i);
  return rank;
}

double spearman(const std::vector<double>& x, const std::vector<double>& y) {
  const std::vector<double> rx = ranks(x), ry = ranks(y);
  const double n = double(x.size());
  double sum = 0.0;
  for (size_t i = 0; i < x.size(); ++i) sum += (rx[i] - ry[i]) * (rx[i] - ry[i]);
  return 1.0 - 6.0 * sum / (n * (n * n - 1.0));
}

}  // namespace

TEST_CASE("the selection's defaults are applied over a command's synthesis options, the rest kept") {
  SynthesisOptions walker;  // what a viewer shows: holes filled, reliability weights, the grid
  walker.holes = HoleMode::Fill;
  walker.blend.weights = BlendWeights::Reliability;
  walker.warp.mesh = SourceMesh::Grid;
  walker.warp.grazingAngleDegrees = 7.5f;
  walker.warp.meshTolerancePixels = 0.5f;
  const SynthesisOptions selection = withSelectionDefaults(walker);
  CHECK(selection.holes == kDefaultErrorHoles);
  CHECK(selection.holes != walker.holes);
  CHECK(selection.blend.weights == kSelectionBlendWeights);
  CHECK(selection.warp.mesh == kSelectionSourceMesh);
  CHECK(selection.warp.grazingAngleDegrees == 7.5f);
  CHECK(selection.warp.meshTolerancePixels == 0.5f);
  // decimate's defaults are these: TriangleErrorSettings' (eval's) but for the selection's own.
  const SynthesisOptions decimate = withSelectionDefaults(TriangleErrorSettings{}.synthesis);
  CHECK(decimate.warp.mesh == kSelectionSourceMesh);
  CHECK(decimate.blend.weights == kSelectionBlendWeights);
  CHECK(decimate.holes == TriangleErrorSettings{}.synthesis.holes);
}

TEST_CASE("a selection's errors load the samples alone, and the probes only when asked, to judge it") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 32, 2);
  const Dataset dataset = Dataset::open(directory / "data");
  // A probe no selection reads: decimate must not open it, eval must name it.
  std::ofstream(directory / "data" / dataset.probe(1).file, std::ios::binary) << "this is not an OpenEXR file";
  TriangleErrorSettings settings;
  settings.width = 32;
  DatasetTriangleErrors samples(dataset, settings, LoadedViews::Samples, true);
  std::vector<double> values(1);
  const Triangle triangle{0, 1, 3};
  samples.computeErrors(std::span<const Triangle>(&triangle, 1), values);
  CHECK(std::isfinite(values[0]));
  testing::requireInputError([&] { DatasetTriangleErrors(dataset, settings, LoadedViews::SamplesAndProbes, true); },
                             dataset.probe(1).file, "cannot read OpenEXR");
}

TEST_CASE("the served-sample cost puts the references where reconstructions fail: the cluttered half") {
  testing::TemporaryDirectory directory;
  testing::writeWallAndClutterDataset(directory / "data", kPaths, kSteps, kWidth, 0);
  const Dataset dataset = Dataset::open(directory / "data");
  TriangleErrorSettings errorSettings;
  errorSettings.width = kWidth;
  DatasetTriangleErrors errors(dataset, errorSettings, LoadedViews::Samples, true);
  SelectionSettings settings;
  settings.decimation.maxError = 0.0;
  settings.decimation.targetSamples = 16;
  const SelectionRun run = selectReferences(dataset, errors, settings, true);
  REQUIRE(run.selection.samples.size() == 16);
  const auto [bare, cluttered] = countHalves(dataset, run.selection.samples);
  MESSAGE("references in the bare half: ", bare, ", in the cluttered half: ", cluttered);
  CHECK(cluttered >= 3 * bare);
  // A selection by position alone splits the same count evenly: the
  // difference is the error's doing, not the geometry's.
  const auto [bareByPosition, clutteredByPosition] =
      countHalves(dataset, kMedoidsSelection(samplePositions(dataset), 16));
  CHECK(std::abs(bareByPosition - clutteredByPosition) <= 2);
}

TEST_CASE("the served-sample cost ranks collapses by what they do to the probes better than the centroid cost") {
  testing::TemporaryDirectory directory;
  testing::writeWallAndClutterDataset(directory / "data", kPaths, kSteps, kWidth, 400);
  const Dataset dataset = Dataset::open(directory / "data");
  TriangleErrorSettings errorSettings;
  errorSettings.width = kWidth;
  DatasetTriangleErrors errors(dataset, errorSettings, LoadedViews::SamplesAndProbes, true);
  // A mesh neither cost chose: the Delaunay triangulation of 40 samples
  // picked by position alone.
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  const ViewMesh mesh = ViewMesh::delaunay(positions, kMedoidsSelection(positions, 40), "test");
  DecimationOptions servedOptions, centroidOptions;
  servedOptions.maxError = centroidOptions.maxError = 0.0;
  servedOptions.fixedBoundary = true;  // the same valid collapses for both
  centroidOptions.cost = CollapseCost::Centroid;
  EdgeCollapseDecimator served(mesh, DecimationErrors{&errors, &errors}, servedOptions);
  EdgeCollapseDecimator centroid(mesh, DecimationErrors{&errors, &errors}, centroidOptions);

  // The truth: how much the collapse raises the total error at the probes,
  // each reconstructed from the triangle around it (errors cached per
  // triangle and probe).
  std::map<std::pair<Triangle, int>, double> known;
  auto probeTotal = [&](const ViewMesh& m) {
    double total = 0.0;
    for (int p = 0; p < dataset.probeCount(); ++p) {
      const glm::vec3 position = dataset.probe(p).position;
      const Triangle triangle = sortedTriangle(m.triangles()[size_t(m.locate(glm::dvec2(position)))]);
      const auto found = known.find({triangle, p});
      const double error = found != known.end() ? found->second
                                                : known[{triangle, p}] = errors.errorAt(triangle, position, errors.probeDisplay(p)).total;
      total += error;
    }
    return total;
  };
  const double before = probeTotal(mesh);
  std::vector<double> servedCosts, centroidCosts, truth;
  std::set<std::pair<int, int>> edges;
  for (const Triangle& t : mesh.triangles()) {
    for (int e = 0; e < 3; ++e) edges.insert(std::minmax(t[size_t(e)], t[size_t((e + 1) % 3)]));
  }
  for (const auto& [a, b] : edges) {
    for (int placement : {a, b}) {
      const std::optional<Collapse> byServed = served.evaluateCollapse(a, b, placement);
      const std::optional<Collapse> byCentroid = centroid.evaluateCollapse(a, b, placement);
      if (!byServed || !byCentroid) continue;
      const ViewMesh after(positions, replayForward(mesh.triangles(), std::span(&*byServed, 1), 1));
      servedCosts.push_back(byServed->cost);
      centroidCosts.push_back(byCentroid->cost);
      truth.push_back(probeTotal(after) - before);
    }
  }
  REQUIRE(truth.size() >= 100);
  const double servedAgreement = spearman(servedCosts, truth), centroidAgreement = spearman(centroidCosts, truth);
  MESSAGE(truth.size(), " collapses; rank correlation with the increase of the probes' total error: served samples ",
          servedAgreement, ", centroid ", centroidAgreement);
  CHECK(servedAgreement > centroidAgreement + 0.1);
  CHECK(servedAgreement > 0.7);
}


TEST_CASE("--relative-error stops where R times the dense mean triangle error says, on a tiny data set") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 4, 32, 0);
  const Dataset dataset = Dataset::open(directory / "data");
  TriangleErrorSettings errorSettings;
  errorSettings.width = 32;
  DatasetTriangleErrors errors(dataset, errorSettings, LoadedViews::Samples, true);
  const ViewMesh dense = ViewMesh::delaunay(samplePositions(dataset), {}, "test");
  std::vector<double> denseErrors(dense.triangles().size());
  errors.computeErrors(dense.triangles(), denseErrors);
  const double denseMean = std::accumulate(denseErrors.begin(), denseErrors.end(), 0.0) / double(denseErrors.size());

  std::map<double, size_t> kept;
  for (const double ratio : {0.9, 1.0, 100.0}) {
    SelectionSettings settings;
    settings.relativeError = ratio;
    settings.decimation.maxError = 0.0;
    settings.refinement.radius = 0.0;
    const SelectionRun run = selectReferences(dataset, errors, settings, true);
    CAPTURE(ratio);
    CHECK(run.denseMeanError == doctest::Approx(denseMean));
    CHECK(run.maxError == doctest::Approx(ratio * denseMean));
    // No collapse above the threshold was made, and the one that stopped
    // the decimation was above it.
    for (const Collapse& collapse : run.selection.collapses) CHECK(collapse.error <= run.maxError);
    if (run.stopReason == StopReason::MaxError) CHECK(run.selection.nextCost > run.maxError);
    kept[ratio] = run.selection.samples.size();
  }
  MESSAGE("samples kept at R = 0.9, 1.0, 100: ", kept[0.9], ", ", kept[1.0], ", ", kept[100.0]);
  // A looser target keeps fewer samples, down to one triangle: the hull's
  // four corners, then one of them removed with its triangle (the last
  // resort, where no collapse is valid).
  CHECK(kept[0.9] > kept[1.0]);
  CHECK(kept[1.0] > kept[100.0]);
  CHECK(kept[100.0] == 3);
}
}  // namespace triwalk
