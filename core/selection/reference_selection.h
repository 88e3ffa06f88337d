#pragma once
// The whole selection of reference views for a data set, as `decimate`
// and `suite` run it: the dense Delaunay triangulation, edge-collapse
// decimation to the threshold or target count, then the refinement at the
// final count (docs/DESIGN.md, "Selection"). Progress goes to the terminal
// unless quiet; Ctrl-C throws Interrupted and nothing is returned.

#include "core/selection/edge_collapse_decimator.h"
#include "core/selection/selection.h"
#include "core/selection/selection_refinement.h"
#include "core/selection/triangle_error.h"

#include <memory>
#include <vector>

namespace triwalk {

// The quality target when none is given: stop before a collapse whose
// error exceeds this many times the dense triangulation's mean triangle
// error (docs/history/RESULTS-2026-11.md, "A quality target for any scene").
inline constexpr double kDefaultRelativeError = 1.36;

struct SelectionSettings {
  DecimationOptions decimation;
  // > 0: decimation.maxError becomes this times the dense triangulation's
  // mean triangle error (Table 1's "initial (a)"), measured first. The
  // paper's 1.85 over its dense 1.36 is 1.36; an absolute error means
  // nothing across scenes whose lighting and texture differ.
  double relativeError = 0.0;
  RefinementOptions refinement;
};

struct SelectionRun {
  Selection selection;  // method, samples, triangles, log; settings left to the caller
  StopReason stopReason = StopReason::None;
  DecimationStatistics statistics;
  RefinementResult refinement;
  size_t collapses = 0;
  int initialSamples = 0;
  double denseMeanError = 0.0;  // measured when a relative error was asked
  double maxError = 0.0;        // the absolute threshold used (0: none)
  double costingSeconds = 0.0;   // the first costing of every edge
  double collapseSeconds = 0.0;  // costing included
  double refinementSeconds = 0.0;
};

// The mean error of triangles (unweighted, as Table 1's mean error column),
// in chunks with progress; stops on Ctrl-C (Interrupted).
double meanTriangleError(TriangleErrorSource& errors, const std::vector<Triangle>& triangles, bool quiet);

// Each dense sample's share of the data set's walkable region
// (sampleAreaWeights): what the selection's served-sample cost and
// refinement weigh samples by, so that sums over samples estimate the
// walkthrough area's error.
std::vector<double> selectionSampleWeights(const Dataset& dataset);

// A decimator from triangles of the data set's samples, set up as
// selectReferences sets up its own: the walkable region serves the samples
// outside every triangle, and the samples weigh their share of it (unless
// options already hold those weights: a caller that needs them again
// computes them once). From the dense triangulation it takes decimate's
// steps; the viewer's live decimation is built here so that they agree.
std::unique_ptr<EdgeCollapseDecimator> datasetDecimator(const Dataset& dataset, std::vector<Triangle> triangles,
                                                        DecimationErrors errors, DecimationOptions options,
                                                        ProgressReporter* costing = nullptr);

// errors: the data set's panoramas at the error width. The samples weigh
// their share of the walkable region unless settings.decimation already
// holds weights (a tile: its samples' shares of the whole capture).
SelectionRun selectReferences(const Dataset& dataset, DatasetTriangleErrors& errors, const SelectionSettings& settings,
                              bool quiet);

// Greedy insertion for a data set (issue 72), by the objective the
// refinement lowers (the served-sample error, samples weighted by their
// share of the region), with the selection's errors. It starts from a
// coverage set: the region-aware uniform baseline at startCount views
// (regionUniformSelection), so every room and corridor its lattice reaches
// already has a triangle; greedy steps see one insertion at a time, and it
// takes three to open a room that has none. Then it inserts until count.
struct InsertionRun {
  std::vector<int> start;   // sorted
  InsertionResult insertion;
  double seconds = 0.0;
  // The references at a count between the start's and the run's: the
  // start and the first insertions, sorted.
  std::vector<int> referencesAt(int count) const;
};
InsertionRun insertReferences(const Dataset& dataset, DatasetTriangleErrors& errors, const RefinementOptions& options,
                              int startCount, int count, bool quiet);

// The start of greedy insertion for a selection of count views: half of
// them (at least 3), so that as many are chosen by the error as by the
// lattice.
int insertionStartCount(int count);

// Those references refined as decimate refines its own (the Delaunay mesh
// of them in the region, then refineSelection): "insertion, then the
// refinement".
std::vector<Triangle> refinedReferences(const Dataset& dataset, DatasetTriangleErrors& errors,
                                        const RefinementOptions& options, std::span<const int> references, bool quiet);

}  // namespace triwalk
