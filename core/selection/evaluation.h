#pragma once
// The paper's Table 1 for a data set (docs/DESIGN.md, "Evaluation"): for each
// selection method, samples, triangles, mean and standard deviation of the
// triangle error, and of the error at the held-out probes (each probe
// reconstructed from the three vertices of the triangle around it, the
// nearest triangle outside the covered area).

#include "core/geometry/view_mesh.h"
#include "core/selection/triangle_error.h"

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace triwalk {

struct MethodEvaluation {
  std::string method;  // initial, uniform, edge_collapse, kmedoids, random
  int samples = 0;
  int triangles = 0;
  double meanError = 0.0, stdError = 0.0;            // over triangles
  double probeMeanError = 0.0, probeStdError = 0.0;  // over probes
  std::vector<double> triangleErrors;
  std::vector<double> probeErrors;
  std::vector<int> probeTriangles;  // the triangle each probe was reconstructed from
};

MethodEvaluation evaluateMesh(const std::string& method, const ViewMesh& mesh, DatasetTriangleErrors& errors);

// The error at every probe only (no triangle errors), each reconstructed
// from the triangle around it; triangles, if given, receives those.
std::vector<double> probeErrors(const ViewMesh& mesh, const DatasetTriangleErrors& errors,
                                std::vector<int>* triangles = nullptr);

// Mean and population standard deviation.
void meanAndDeviation(const std::vector<double>& values, double& mean, double& deviation);

// Probe by probe, a candidate against a baseline on the same probes: the
// mean of the differences (candidate - baseline, negative = candidate
// better), its standard error (sample deviation / sqrt(n)), and at how
// many probes the candidate is lower. The probes are shared, so the paired
// error is far smaller than the two means' spreads would suggest.
struct PairedComparison {
  double meanDifference = 0.0;
  double standardError = 0.0;
  int candidateLower = 0;
};

PairedComparison compareProbeErrors(const std::vector<double>& candidate, const std::vector<double>& baseline);

// The positions outside every triangle of a selection's mesh (further than
// a micrometre from all of them): where collapses shrank the boundary, or a
// removal took a loop's triangles, a walker or a probe is served from a
// triangle that may be far away.
struct UncoveredPositions {
  int count = 0;
  double farthest = 0.0;  // metres from the nearest triangle
};

UncoveredPositions uncoveredPositions(const ViewMesh& mesh, std::span<const glm::dvec2> positions);

// How many views a method needs to reach a probe error (the paper's "fewer
// views for the same quality"), along its count curve: (count, probe mean
// error) points, counts ascending. Where the error first falls to the
// target or below it, the count is interpolated linearly between that
// point and the one before; already there at the first point: at most
// that count; never there: more than the last count.
struct ViewsForError {
  enum class Bound { Interpolated, AtMost, MoreThan };
  double views = 0.0;
  Bound bound = Bound::Interpolated;
};
ViewsForError viewsForError(std::span<const std::pair<int, double>> curve, double target);
// "23.4", "<= 16", "> 64".
std::string formatViews(const ViewsForError& views);

}  // namespace triwalk
