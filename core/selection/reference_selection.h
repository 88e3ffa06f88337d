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

namespace triwalk {

struct SelectionSettings {
  DecimationOptions decimation;
  RefinementOptions refinement;
  // Weigh each dense sample by its share of the walkable region (see
  // sampleAreaWeights) in the served-sample cost and the refinement.
  bool areaWeights = true;
};

struct SelectionRun {
  Selection selection;  // method, samples, triangles, log; settings left to the caller
  StopReason stopReason = StopReason::None;
  DecimationStatistics statistics;
  RefinementResult refinement;
  size_t collapses = 0;
  int initialSamples = 0;
  double costingSeconds = 0.0;   // the first costing of every edge
  double collapseSeconds = 0.0;  // costing included
  double refinementSeconds = 0.0;
};

// errors: the data set's panoramas at the error width.
SelectionRun selectReferences(const Dataset& dataset, DatasetTriangleErrors& errors, const SelectionSettings& settings,
                              bool quiet);

}  // namespace triwalk
