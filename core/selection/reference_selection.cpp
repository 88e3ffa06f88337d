#include "core/selection/reference_selection.h"

#include "core/selection/baselines.h"
#include "core/selection/walking_distances.h"
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
  if (settings.refinement.sampleWeights.empty()) settings.refinement.sampleWeights = settings.decimation.sampleWeights;
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

namespace {

// The options the selection's own refinement runs with on this data set:
// the region, and the samples' shares of it as weights.
RefinementOptions datasetRefinementOptions(const Dataset& dataset, RefinementOptions options,
                                           const WalkableRegion& region) {
  options.region = &region;
  if (options.sampleWeights.empty()) options.sampleWeights = selectionSampleWeights(dataset);
  return options;
}

}  // namespace

std::vector<int> InsertionRun::referencesAt(int count) const {
  const int inserted = count - int(start.size());
  TRIWALK_CHECK(inserted >= 0 && inserted <= int(insertion.inserted.size()), "a count greedy insertion passed through");
  std::vector<int> references = start;
  references.insert(references.end(), insertion.inserted.begin(), insertion.inserted.begin() + inserted);
  std::sort(references.begin(), references.end());
  return references;
}

int insertionStartCount(int count) { return std::max(3, (count + 1) / 2); }

InsertionRun insertReferences(const Dataset& dataset, DatasetTriangleErrors& errors, const RefinementOptions& options,
                              int startCount, int count, bool quiet) {
  const auto began = std::chrono::steady_clock::now();
  const WalkableRegion region = dataset.walkableRegion();
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  const WalkingDistances walking(positions, region);
  InsertionRun run;
  run.start = regionUniformSelection(uniformSelection(dataset, startCount), walking, positions, region, startCount);
  const RefinementOptions insertionOptions = datasetRefinementOptions(dataset, options, region);
  CachingReconstructionErrors sampleErrors(errors);
  ProgressReporter progress("greedy insertion", size_t(std::max(0, count - int(run.start.size()))), quiet);
  run.insertion = insertGreedily(positions, run.start, count, sampleErrors, insertionOptions, &progress);
  progress.finish();
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return run;
}

std::vector<Triangle> refinedReferences(const Dataset& dataset, DatasetTriangleErrors& errors,
                                        const RefinementOptions& options, std::span<const int> references, bool quiet) {
  const WalkableRegion region = dataset.walkableRegion();
  const ViewMesh mesh = datasetMesh(dataset, references, "greedy insertion");
  CachingReconstructionErrors sampleErrors(errors);
  ProgressReporter refining("refine: move references", 0, quiet);
  const RefinementResult refined = refineSelection(mesh.positions(), mesh.triangles(), sampleErrors,
                                                   datasetRefinementOptions(dataset, options, region), &refining);
  refining.finish();
  return refined.triangles;
}

}  // namespace triwalk
