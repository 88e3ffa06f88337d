#include "core/selection/evaluation.h"

#include "core/support/errors.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace triwalk {

void meanAndDeviation(const std::vector<double>& values, double& mean, double& deviation) {
  mean = deviation = 0.0;
  if (values.empty()) return;
  for (double v : values) mean += v;
  mean /= double(values.size());
  for (double v : values) deviation += (v - mean) * (v - mean);
  deviation = std::sqrt(deviation / double(values.size()));
}

PairedComparison compareProbeErrors(const std::vector<double>& candidate, const std::vector<double>& baseline) {
  TRIWALK_CHECK(candidate.size() == baseline.size(), "paired comparison needs the same probes");
  PairedComparison comparison;
  const size_t n = candidate.size();
  if (n == 0) return comparison;
  for (size_t i = 0; i < n; ++i) {
    comparison.meanDifference += candidate[i] - baseline[i];
    comparison.candidateLower += candidate[i] < baseline[i];
  }
  comparison.meanDifference /= double(n);
  if (n < 2) return comparison;
  double sumOfSquares = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double deviation = candidate[i] - baseline[i] - comparison.meanDifference;
    sumOfSquares += deviation * deviation;
  }
  comparison.standardError = std::sqrt(sumOfSquares / double(n - 1)) / std::sqrt(double(n));
  return comparison;
}

std::vector<double> probeErrors(const ViewMesh& mesh, const DatasetTriangleErrors& errors, std::vector<int>* triangles) {
  const Dataset& dataset = errors.dataset();
  std::vector<int> located(size_t(dataset.probeCount()));
  std::vector<double> result(located.size());
  for (int p = 0; p < dataset.probeCount(); ++p) located[size_t(p)] = mesh.locate(glm::dvec2(dataset.probe(p).position));
  tbb::parallel_for(0, dataset.probeCount(), [&](int p) {
    const Triangle& triangle = mesh.triangles()[size_t(located[size_t(p)])];
    result[size_t(p)] = errors.errorAt(triangle, dataset.probe(p).position, errors.probeDisplay(p)).total;
  });
  if (triangles) *triangles = std::move(located);
  return result;
}

MethodEvaluation evaluateMesh(const std::string& method, const ViewMesh& mesh, DatasetTriangleErrors& errors) {
  MethodEvaluation evaluation;
  evaluation.method = method;
  evaluation.samples = mesh.vertexCount();
  evaluation.triangles = mesh.triangleCount();
  evaluation.triangleErrors.resize(mesh.triangles().size());
  errors.computeErrors(mesh.triangles(), evaluation.triangleErrors);
  meanAndDeviation(evaluation.triangleErrors, evaluation.meanError, evaluation.stdError);

  evaluation.probeErrors = probeErrors(mesh, errors, &evaluation.probeTriangles);
  meanAndDeviation(evaluation.probeErrors, evaluation.probeMeanError, evaluation.probeStdError);
  return evaluation;
}

UncoveredPositions uncoveredPositions(const ViewMesh& mesh, std::span<const glm::dvec2> positions) {
  constexpr double kOnTheMesh = 1e-6;  // metres: a position on an edge rounds either way
  UncoveredPositions uncovered;
  for (glm::dvec2 position : positions) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int t = 0; t < mesh.triangleCount() && nearest > kOnTheMesh; ++t) {
      nearest = std::min(nearest, mesh.distanceToTriangle(t, position));
    }
    if (nearest <= kOnTheMesh) continue;
    ++uncovered.count;
    uncovered.farthest = std::max(uncovered.farthest, nearest);
  }
  return uncovered;
}

ViewsForError viewsForError(std::span<const std::pair<int, double>> curve, double target) {
  TRIWALK_CHECK(!curve.empty(), "a count curve has a point");
  if (curve[0].second <= target) return {double(curve[0].first), ViewsForError::Bound::AtMost};
  for (size_t i = 1; i < curve.size(); ++i) {
    const auto [count, error] = curve[i];
    if (error > target) continue;
    const auto [before, errorBefore] = curve[i - 1];
    const double t = (errorBefore - target) / (errorBefore - error);
    return {double(before) + t * double(count - before), ViewsForError::Bound::Interpolated};
  }
  return {double(curve.back().first), ViewsForError::Bound::MoreThan};
}

std::string formatViews(const ViewsForError& views) {
  char text[32];
  switch (views.bound) {
    case ViewsForError::Bound::AtMost: std::snprintf(text, sizeof text, "<= %.0f", views.views); break;
    case ViewsForError::Bound::MoreThan: std::snprintf(text, sizeof text, "> %.0f", views.views); break;
    case ViewsForError::Bound::Interpolated: std::snprintf(text, sizeof text, "%.1f", views.views); break;
  }
  return text;
}

}  // namespace triwalk
