// The viewer's live decimation, driven as its panel drives it: a run to a
// relative error stops where decimate --relative-error stops, and a saved
// selection says where it stopped.

#include "app/viewer/decimation_session.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection_recipe.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <thread>

namespace triwalk {

namespace {

// The snapshot once the session's queued work is done (the panoramas
// loaded and the run finished).
DecimationSession::Snapshot waitUntilIdle(const DecimationSession& session) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  DecimationSession::Snapshot snapshot = session.snapshot();
  while (snapshot.busy && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    snapshot = session.snapshot();
  }
  REQUIRE_FALSE(snapshot.busy);
  return snapshot;
}

std::vector<Triangle> sortedTriangles(std::vector<Triangle> triangles) {
  for (Triangle& t : triangles) t = canonicalTriangle(t);
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

}  // namespace

TEST_CASE("the viewer's run to a relative error measures the dense mean and stops where decimate does") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 5, 3, 64, 1);
  const Dataset dataset = Dataset::open(directory / "data");
  TriangleErrorSettings errorSettings;
  errorSettings.width = 64;
  errorSettings.synthesis = withSelectionDefaults(errorSettings.synthesis);
  constexpr double kFactor = 1.1;  // stops this data set between its ends

  DatasetTriangleErrors errors(dataset, errorSettings, LoadedViews::Samples, true);
  SelectionSettings settings;
  settings.relativeError = kFactor;
  settings.refinement.radius = 0.0;
  const SelectionRun decimate = selectReferences(dataset, errors, settings, true);
  // The threshold stops it short of both ends, so where it stops is a test.
  REQUIRE(decimate.stopReason == StopReason::MaxError);
  REQUIRE(decimate.collapses > 0);

  DecimationSession session(dataset, errorSettings, DecimationOptions{}, std::nullopt);
  session.runToRelativeError(kFactor);
  const DecimationSession::Snapshot done = waitUntilIdle(session);
  INFO("status: " << done.status);
  CHECK(done.status.rfind("reached error", 0) == 0);
  CHECK(done.denseMeanError == decimate.denseMeanError);
  CHECK(done.step == int(decimate.collapses));
  CHECK(done.samples == int(decimate.selection.samples.size()));
  CHECK(sortedTriangles(done.triangles) == sortedTriangles(decimate.selection.triangles));

  // A saved selection names the threshold, where the viewer starts again.
  const nlohmann::json saved = session.selection().settings;
  CHECK(saved.at("relative_error").get<double>() == kFactor);
  CHECK(saved.at("max_error").get<double>() == kFactor * decimate.denseMeanError);
  // One writer of a selection's settings: decimate's recipe, every setting
  // of the errors and collapses the session ran with, no refinement.
  const SelectionRecipe recipe = readSelectionRecipe(JsonObject(saved, "saved", "settings"), dataset);
  CHECK(describeSelectionRecipe(recipe).dump() == saved.dump());
  CHECK(describeSelectionErrors(recipe.errors) == describeSelectionErrors(errorSettings));
  CHECK(recipe.selection.refinement.radius == 0.0);

  // The same threshold as an absolute error: no further step, from the log.
  session.runToError(kFactor * decimate.denseMeanError);
  CHECK(waitUntilIdle(session).step == int(decimate.collapses));

  // A step back leaves the threshold: saved there, the file names none (0;
  // reopened, "run to error" starts at decimate's default), and names it
  // again once the person steps forward to where the run stopped.
  session.stepBack(1);
  CHECK(waitUntilIdle(session).step == int(decimate.collapses) - 1);
  const nlohmann::json steppedBack = session.selection().settings;
  CHECK(steppedBack.at("max_error").get<double>() == 0.0);
  CHECK(steppedBack.at("relative_error").get<double>() == 0.0);
  session.stepForward(1);
  CHECK(waitUntilIdle(session).step == int(decimate.collapses));
  CHECK(session.selection().settings.at("max_error").get<double>() == kFactor * decimate.denseMeanError);
}

}  // namespace triwalk
