#include "core/selection/reference_selection.h"

#include "core/support/errors.h"
#include "core/support/progress.h"

#include <chrono>
#include <numeric>

namespace triwalk {

double meanTriangleError(TriangleErrorSource& errors, const std::vector<Triangle>& triangles, bool quiet) {
  TRIWALK_CHECK(!triangles.empty(), "no triangles to measure");
  ProgressReporter progress("dense triangle errors", triangles.size(), quiet);
  const std::vector<double> values =
      computeInChunks(std::span<const Triangle>(triangles), &progress,
                      [&](std::span<const Triangle> batch, std::span<double> batchErrors) {
                        errors.computeErrors(batch, batchErrors);
                      });
  progress.finish();
  return std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
}

std::vector<double> selectionSampleWeights(const Dataset& dataset) {
  return sampleAreaWeights(samplePositions(dataset), dataset.walkableRegion());
}

std::unique_ptr<EdgeCollapseDecimator> datasetDecimator(const Dataset& dataset, std::vector<Triangle> triangles,
                                                        DecimationErrors errors, DecimationOptions options,
                                                        ProgressReporter* costing) {
  if (options.sampleWeights.empty()) options.sampleWeights = selectionSampleWeights(dataset);
  return std::make_unique<EdgeCollapseDecimator>(datasetTriangles(dataset, std::move(triangles)), errors, options, costing);
}

SelectionRun selectReferences(const Dataset& dataset, DatasetTriangleErrors& errors, const SelectionSettings& requested,
                              bool quiet) {
  SelectionRun run;
  const ViewMesh initial = datasetMesh(dataset, {}, dataset.manifestPath().string());
  SelectionSettings settings = requested;
  const WalkableRegion region = dataset.walkableRegion();
  settings.refinement.region = &region;
  if (settings.decimation.sampleWeights.empty()) settings.decimation.sampleWeights = selectionSampleWeights(dataset);
  settings.refinement.sampleWeights = settings.decimation.sampleWeights;
  run.initialSamples = initial.vertexCount();
  if (settings.relativeError > 0.0) {
    run.denseMeanError = meanTriangleError(errors, initial.triangles(), quiet);
    settings.decimation.maxError = settings.relativeError * run.denseMeanError;
  }
  run.maxError = settings.decimation.maxError;
  // One cache of dense-sample errors serves the collapses and the
  // refinement, which starts from the errors the collapses left.
  CachingReconstructionErrors sampleErrors(errors);
  const auto start = std::chrono::steady_clock::now();
  ProgressReporter costing("cost every edge", 0, quiet);
  const std::unique_ptr<EdgeCollapseDecimator> decimator =
      datasetDecimator(dataset, initial.triangles(), DecimationErrors{&errors, &sampleErrors}, settings.decimation, &costing);
  costing.finish();
  run.costingSeconds = costing.elapsedSeconds();
  const int target = settings.decimation.targetSamples;
  const size_t expected = target > 0 ? size_t(std::max(0, initial.vertexCount() - target)) : 0;
  ProgressReporter progress("collapse", expected, quiet);
  run.stopReason = decimator->run(&progress);
  progress.finish();
  if (run.stopReason == StopReason::Interrupted) throw Interrupted();
  run.collapseSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.statistics = decimator->statistics();
  run.collapses = decimator->log().size();

  ProgressReporter refining("refine: move references", 0, quiet || settings.refinement.radius == 0.0);
  run.refinement = refineSelection(initial.positions(), decimator->mesh().triangles(), sampleErrors, settings.refinement,
                                   &refining);
  refining.finish();
  run.refinementSeconds = refining.elapsedSeconds();

  const ViewMesh final(initial.positions(), run.refinement.triangles);
  Selection& selection = run.selection;
  selection.method = "edge_collapse";
  selection.samples = final.vertices();
  selection.triangles = final.triangles();
  selection.initialTriangles = initial.triangles();
  selection.collapses = decimator->log();
  selection.collapses.insert(selection.collapses.end(), run.refinement.moves.begin(), run.refinement.moves.end());
  selection.stopReason = stopReasonName(run.stopReason);
  selection.nextCost = run.stopReason == StopReason::MaxError ? decimator->lowestRefusedError() : decimator->nextCost();
  return run;
}

}  // namespace triwalk
