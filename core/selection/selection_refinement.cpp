#include "core/selection/selection_refinement.h"

#include "core/geometry/view_mesh.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

namespace triwalk {

namespace {

// Which triangle reconstructs each dense sample that is not a reference.
class ObjectiveEvaluator {
public:
  ObjectiveEvaluator(std::span<const glm::dvec2> positions, std::span<const double> weights,
                     const WalkableRegion* region, ReconstructionErrorSource& errors, RefinementResult& result)
      : positions_(positions.begin(), positions.end()), weights_(weights.begin(), weights.end()), region_(region),
        errors_(errors), result_(result) {}

  std::vector<SampleReconstruction> assignments(const ViewMesh& mesh) const {
    std::vector<SampleReconstruction> requests;
    const std::vector<int>& references = mesh.vertices();
    int hint = -1;
    for (int i = 0; i < int(positions_.size()); ++i) {
      if (std::binary_search(references.begin(), references.end(), i)) continue;
      hint = mesh.locate(positions_[size_t(i)], hint);
      requests.push_back({sortedTriangle(mesh.triangles()[size_t(hint)]), i});
    }
    return requests;
  }

  // Computes, in one parallel batch, every error the given assignments
  // need that is not cached yet.
  void compute(const std::vector<std::vector<SampleReconstruction>>& batches) {
    std::set<SampleReconstruction> missing;
    for (const auto& batch : batches) {
      for (const SampleReconstruction& request : batch) {
        if (known_.count(request)) {
          ++result_.cacheHits;
        } else {
          missing.insert(request);
        }
      }
    }
    if (missing.empty()) return;
    const std::vector<SampleReconstruction> requests(missing.begin(), missing.end());
    std::vector<double> values(requests.size());
    errors_.computeReconstructionErrors(requests, values);
    for (size_t i = 0; i < requests.size(); ++i) known_.emplace(requests[i], values[i]);
    result_.errorsComputed += requests.size();
  }

  double mean(const std::vector<SampleReconstruction>& assignment) const {
    double sum = 0.0, weightSum = 0.0;
    for (const SampleReconstruction& request : assignment) {
      const double weight = weights_.empty() ? 1.0 : weights_[size_t(request.destination)];
      sum += weight * known_.at(request);
      weightSum += weight;
    }
    return weightSum > 0.0 ? sum / weightSum : 0.0;
  }

  std::optional<ViewMesh> triangulate(const std::vector<int>& references) const {
    return ViewMesh::tryDelaunay(positions_, references, region_);
  }

private:
  std::vector<glm::dvec2> positions_;
  std::vector<double> weights_;
  const WalkableRegion* region_;
  ReconstructionErrorSource& errors_;
  RefinementResult& result_;
  std::map<SampleReconstruction, double> known_;
};

std::vector<Triangle> without(const std::vector<Triangle>& from, const std::vector<Triangle>& remove) {
  std::vector<Triangle> result;
  std::set_difference(from.begin(), from.end(), remove.begin(), remove.end(), std::back_inserter(result));
  return result;
}

std::vector<int> neighboursOf(const ViewMesh& mesh, int sample) {
  std::vector<int> neighbours;
  for (int t : mesh.trianglesAround(sample)) {
    for (int v : mesh.triangles()[size_t(t)]) {
      if (v != sample) neighbours.push_back(v);
    }
  }
  return neighbours;
}

}  // namespace

double neighbourhoodRadius(std::span<const glm::dvec2> positions) {
  constexpr size_t kNeighbours = 8;
  std::vector<double> eighth(positions.size(), 0.0);
  tbb::parallel_for(size_t(0), positions.size(), [&](size_t i) {
    std::vector<double> distances;
    for (size_t j = 0; j < positions.size(); ++j) {
      if (j != i) distances.push_back(glm::length(positions[j] - positions[i]));
    }
    if (distances.empty()) return;
    const size_t k = std::min(kNeighbours, distances.size()) - 1;
    std::nth_element(distances.begin(), distances.begin() + std::ptrdiff_t(k), distances.end());
    eighth[i] = distances[k];
  });
  if (eighth.empty()) return 0.0;
  const size_t quartile = eighth.size() / 4;
  std::nth_element(eighth.begin(), eighth.begin() + std::ptrdiff_t(quartile), eighth.end());
  return 1.01 * eighth[quartile];
}

RefinementResult refineSelection(std::span<const glm::dvec2> positions, const std::vector<Triangle>& current,
                                 ReconstructionErrorSource& errors, const RefinementOptions& options,
                                 ProgressReporter* progress) {
  RefinementResult result;
  result.radius = options.radius.value_or(neighbourhoodRadius(positions));
  ObjectiveEvaluator evaluator(positions, options.sampleWeights, options.region, errors, result);
  TRIWALK_CHECK(!current.empty(), "refining a selection needs its triangles");
  ViewMesh mesh(std::vector<glm::dvec2>(positions.begin(), positions.end()), current, sharedRegion(options.region));
  std::vector<int> references = mesh.vertices();  // sorted
  std::vector<SampleReconstruction> assignment = evaluator.assignments(mesh);
  evaluator.compute({assignment});
  double objective = evaluator.mean(assignment);
  result.objectiveBefore = objective;
  result.triangles = mesh.triangles();
  if (result.radius <= 0.0) {
    result.objectiveAfter = objective;
    return result;
  }

  std::set<int> flagged(references.begin(), references.end());
  while (!flagged.empty() && result.passes < options.maxPasses) {
    ++result.passes;
    const std::vector<int> examine(flagged.begin(), flagged.end());
    flagged.clear();
    if (progress) progress->setTotal(progress->done() + examine.size());  // time left: of this pass
    for (int moving : examine) {
      throwIfInterrupted();
      if (progress) progress->advance();
      const auto at = std::find(references.begin(), references.end(), moving);
      if (at == references.end()) continue;  // moved away earlier in this pass
      std::vector<int> candidates;
      std::vector<ViewMesh> meshes;
      std::vector<std::vector<SampleReconstruction>> assignments;
      for (int c = 0; c < int(positions.size()); ++c) {
        if (std::binary_search(references.begin(), references.end(), c)) continue;
        if (glm::length(positions[size_t(c)] - positions[size_t(moving)]) > result.radius) continue;
        std::vector<int> moved = references;
        moved[size_t(at - references.begin())] = c;
        std::sort(moved.begin(), moved.end());
        std::optional<ViewMesh> candidate = evaluator.triangulate(moved);
        if (!candidate) continue;
        candidates.push_back(c);
        assignments.push_back(evaluator.assignments(*candidate));
        meshes.push_back(std::move(*candidate));
      }
      evaluator.compute(assignments);
      int best = -1;
      double bestObjective = objective;
      for (size_t k = 0; k < candidates.size(); ++k) {
        const double value = evaluator.mean(assignments[k]);
        if (value < bestObjective) bestObjective = value, best = int(k);
      }
      if (best < 0) continue;

      const ViewMesh& next = meshes[size_t(best)];
      Collapse move;
      move.first = moving;
      move.placement = candidates[size_t(best)];
      move.kind = PlacementKind::Relocation;
      move.cost = bestObjective;
      move.error = bestObjective;
      move.removed = without(mesh.triangles(), next.triangles());
      move.added = without(next.triangles(), mesh.triangles());
      result.moves.push_back(std::move(move));
      for (int v : neighboursOf(mesh, moving)) flagged.insert(v);
      for (int v : neighboursOf(next, candidates[size_t(best)])) flagged.insert(v);
      flagged.insert(candidates[size_t(best)]);
      *at = candidates[size_t(best)];
      std::sort(references.begin(), references.end());
      mesh = next;
      objective = bestObjective;
      if (progress) {
        char status[96];
        std::snprintf(status, sizeof status, "pass %d, %zu moves, mean error %.4f", result.passes, result.moves.size(),
                      objective);
        progress->setStatus(status);
      }
    }
  }
  result.objectiveAfter = objective;
  result.triangles = mesh.triangles();
  return result;
}

}  // namespace triwalk
