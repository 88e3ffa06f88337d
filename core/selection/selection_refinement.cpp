#include "core/selection/selection_refinement.h"

#include "core/geometry/view_mesh.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

namespace triwalk {

namespace {

// Which triangle reconstructs each dense sample that is not a reference.
class ObjectiveEvaluator {
public:
  ObjectiveEvaluator(std::span<const glm::dvec2> positions, std::span<const double> weights,
                     const WalkableRegion* region, ReconstructionErrorSource& errors, RefinementResult& result)
      : positions_(positions.begin(), positions.end()), weights_(weights.begin(), weights.end()), region_(region),
        errors_(errors), result_(result) {}

  // Every sample's, or only those of the screened subset.
  std::vector<SampleReconstruction> assignments(const ViewMesh& mesh, bool screenedOnly = false) const {
    std::vector<SampleReconstruction> requests;
    const std::vector<int>& references = mesh.vertices();
    int hint = -1;
    for (int i = 0; i < int(positions_.size()); ++i) {
      if (screenedOnly && !screened_[size_t(i)]) continue;
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

  // The screened subset: the given share of the samples, those of lowest
  // samplePricingRank; 0: none (no screening).
  void screen(double share) {
    screened_.assign(positions_.size(), 0);
    const size_t count = size_t(std::ceil(share * double(positions_.size())));
    if (count == 0) return;
    std::vector<std::pair<uint64_t, int>> ranked;
    for (int i = 0; i < int(positions_.size()); ++i) ranked.emplace_back(samplePricingRank(i), i);
    std::sort(ranked.begin(), ranked.end());
    for (size_t k = 0; k < std::min(count, ranked.size()); ++k) screened_[size_t(ranked[k].second)] = 1;
  }

private:
  std::vector<glm::dvec2> positions_;
  std::vector<double> weights_;
  const WalkableRegion* region_;
  ReconstructionErrorSource& errors_;
  RefinementResult& result_;
  std::map<SampleReconstruction, double> known_;
  std::vector<char> screened_;
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

std::vector<int> exchangeCandidates(std::span<const glm::dvec2> positions, std::span<const int> references) {
  std::vector<double> nearest(positions.size(), std::numeric_limits<double>::infinity());
  tbb::parallel_for(size_t(0), positions.size(), [&](size_t i) {
    for (size_t j = 0; j < positions.size(); ++j) {
      if (j != i) nearest[i] = std::min(nearest[i], glm::length(positions[j] - positions[i]));
    }
  });
  if (positions.size() < 2) return {};
  std::nth_element(nearest.begin(), nearest.begin() + std::ptrdiff_t(nearest.size() / 2), nearest.end());
  const double apart = 1.5 * nearest[nearest.size() / 2];
  std::vector<int> candidates;
  for (int c = 0; c < int(positions.size()); ++c) {
    if (std::find(references.begin(), references.end(), c) != references.end()) continue;
    const bool crowded = std::any_of(candidates.begin(), candidates.end(), [&](int other) {
      return glm::length(positions[size_t(other)] - positions[size_t(c)]) < apart;
    });
    if (!crowded) candidates.push_back(c);
  }
  return candidates;
}

namespace {

// The selection being refined: its references (sorted), their mesh and the
// objective there, and the log of what moved.
class Refinement {
public:
  Refinement(std::span<const glm::dvec2> positions, const std::vector<Triangle>& current,
             ReconstructionErrorSource& errors, const RefinementOptions& options, RefinementResult& result)
      : positions_(positions),
        options_(options),
        evaluator_(positions, options.sampleWeights, options.region, errors, result),
        mesh_(std::vector<glm::dvec2>(positions.begin(), positions.end()), current, sharedRegion(options.region)),
        references_(mesh_.vertices()),
        result_(result),
        start_(mesh_) {
    evaluator_.screen(options.screenedShare);
    const std::vector<SampleReconstruction> assignment = evaluator_.assignments(mesh_);
    evaluator_.compute({assignment});
    objective_ = startObjective_ = evaluator_.mean(assignment);
  }

  double objective() const { return objective_; }
  const ViewMesh& mesh() const { return mesh_; }

  // Moves are judged on Delaunay meshes of the references, so they start
  // from the Delaunay mesh of the given references, even where the given
  // mesh (a decimated one, whose boundary shrank where that paid) is
  // better: every move from it would otherwise be compared with a mesh no
  // move can reproduce, and none would be made. Nothing is logged yet.
  void startFromDelaunay() {
    const std::vector<Candidate> delaunay = evaluate({references_});
    if (!delaunay[0].mesh) return;
    mesh_ = *delaunay[0].mesh;
    objective_ = delaunay[0].objective;
  }

  // Back to the given mesh, with no moves, unless the moves ended below it.
  void keepTheBetter() {
    if (!result_.moves.empty() && objective_ < startObjective_) return;
    result_.moves.clear();
    result_.exchanges = 0;
    mesh_ = start_;
    references_ = start_.vertices();
    objective_ = startObjective_;
    screenedObjective_.reset();
  }

  // Local moves until none helps; then, as long as an exchange helps (at
  // most maxExchanges), the exchange and local moves around it again. So
  // the result is never worse than local moves alone, and no single move
  // of either kind improves it.
  void refine(int maxExchanges, ProgressReporter* progress) {
    moveLocally(std::set<int>(references_.begin(), references_.end()), progress);
    while (result_.exchanges < maxExchanges) {
      throwIfInterrupted();
      const ViewMesh before = mesh_;
      const std::optional<std::pair<int, int>> exchanged = bestExchange();
      if (!exchanged) break;
      ++result_.exchanges;
      const auto [removed, added] = *exchanged;
      std::set<int> flagged = {added};
      for (int v : neighboursOf(before, removed)) flagged.insert(v);
      for (int v : neighboursOf(mesh_, added)) flagged.insert(v);
      std::erase_if(flagged, [&](int v) { return !std::binary_search(references_.begin(), references_.end(), v); });
      moveLocally(flagged, progress);
    }
  }

private:
  // Local moves within radius, pass after pass over the flagged references
  // (at most maxPasses).
  void moveLocally(std::set<int> flagged, ProgressReporter* progress) {
    int passes = 0;
    while (!flagged.empty() && passes < options_.maxPasses) {
      ++passes;
      ++result_.passes;
      const std::vector<int> examine(flagged.begin(), flagged.end());
      flagged.clear();
      if (progress) progress->setTotal(progress->done() + examine.size());  // time left: of this pass
      for (int moving : examine) {
        throwIfInterrupted();
        if (progress) progress->advance();
        if (!std::binary_search(references_.begin(), references_.end(), moving))
          continue;  // moved away earlier in this pass
        std::vector<std::vector<int>> tries;
        for (int c = 0; c < int(positions_.size()); ++c) {
          if (std::binary_search(references_.begin(), references_.end(), c)) continue;
          if (glm::length(positions_[size_t(c)] - positions_[size_t(moving)]) > result_.radius) continue;
          tries.push_back(replaced(moving, c));
        }
        if (screening()) tries = screenedBest(tries, screenedObjective(), kMovesScored);
        const std::vector<Candidate> candidates = evaluate(tries);
        const Candidate* best = nullptr;
        for (const Candidate& candidate : candidates) {
          if (candidate.objective < (best ? best->objective : objective_)) best = &candidate;
        }
        if (!best) continue;
        const int placement = best->placement;
        for (int v : neighboursOf(mesh_, moving)) flagged.insert(v);
        for (int v : neighboursOf(*best->mesh, placement)) flagged.insert(v);
        flagged.insert(placement);
        accept(moving, *best);
        if (progress) {
          char status[96];
          std::snprintf(status, sizeof status, "%d exchanges, %zu moves, mean error %.4f", result_.exchanges,
                        result_.moves.size(), objective_);
          progress->setStatus(status);
        }
      }
    }
  }

  // A set of references tried: its mesh (none if no triangle of it lies
  // in the region), the objective there, and the sample it added (-1 if
  // none).
  struct Candidate {
    std::vector<int> references;
    std::optional<ViewMesh> mesh;
    double objective = std::numeric_limits<double>::infinity();
    int placement = -1;
  };

  // The references with one replaced (from -1: one added; to -1: one removed), sorted.
  std::vector<int> replaced(int from, int to) const {
    std::vector<int> result;
    for (int r : references_) {
      if (r != from) result.push_back(r);
    }
    if (to >= 0) result.push_back(to);
    std::sort(result.begin(), result.end());
    return result;
  }

  // How many screened candidates are scored exactly: local moves of one
  // reference, and exchanges.
  static constexpr size_t kMovesScored = 2, kExchangesScored = 4;

  enum class Scope { AllSamples, Screened };
  bool screening() const { return options_.screenedShare > 0.0; }

  // The screened objective of the references, computed once per selection
  // (the errors come from the cache, the triangulation would not).
  double screenedObjective() {
    if (!screenedObjective_) screenedObjective_ = evaluate({references_}, Scope::Screened)[0].objective;
    return *screenedObjective_;
  }

  // Of reference sets, the `keep` whose screened objective is lowest and
  // below `below`, in the order given (so ties still go to the earlier).
  std::vector<std::vector<int>> screenedBest(const std::vector<std::vector<int>>& sets, double below, size_t keep) {
    const std::vector<Candidate> screened = evaluate(sets, Scope::Screened);
    std::vector<std::pair<double, size_t>> ranked;
    for (size_t k = 0; k < screened.size(); ++k) {
      if (screened[k].objective < below) ranked.emplace_back(screened[k].objective, k);
    }
    std::sort(ranked.begin(), ranked.end());
    ranked.resize(std::min(ranked.size(), keep));
    std::sort(ranked.begin(), ranked.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
    std::vector<std::vector<int>> best;
    for (const auto& [objective, k] : ranked) best.push_back(sets[k]);
    return best;
  }

  // Triangulates and scores reference sets, the errors they need in one
  // parallel batch; results in the order given.
  std::vector<Candidate> evaluate(const std::vector<std::vector<int>>& sets, Scope scope = Scope::AllSamples) {
    std::vector<Candidate> candidates(sets.size());
    std::vector<std::vector<SampleReconstruction>> assignments(sets.size());
    tbb::parallel_for(size_t(0), sets.size(), [&](size_t k) {
      Candidate& candidate = candidates[k];
      candidate.references = sets[k];
      for (int r : sets[k]) {
        if (!std::binary_search(references_.begin(), references_.end(), r)) candidate.placement = r;
      }
      candidate.mesh = evaluator_.triangulate(sets[k]);
      if (candidate.mesh) assignments[k] = evaluator_.assignments(*candidate.mesh, scope == Scope::Screened);
    });
    evaluator_.compute(assignments);
    for (size_t k = 0; k < sets.size(); ++k) {
      if (candidates[k].mesh) candidates[k].objective = evaluator_.mean(assignments[k]);
    }
    return candidates;
  }

  // The best exchange, made if it lowers the objective; its (reference,
  // sample), or nothing. Losses and gains are measured against the
  // Delaunay mesh of the references, which the first exchange replaces
  // the decimated mesh with.
  std::optional<std::pair<int, int>> bestExchange() {
    constexpr size_t kRemovals = 8, kInsertions = 16, kPairs = 16;
    const Scope scope = screening() ? Scope::Screened : Scope::AllSamples;
    const std::vector<Candidate> base = evaluate({references_}, scope);
    if (!base[0].mesh) return std::nullopt;
    std::vector<std::vector<int>> sets;
    for (int v : references_) sets.push_back(replaced(v, -1));
    const std::vector<int> insertions = exchangeCandidates(positions_, references_);
    for (int c : insertions) sets.push_back(replaced(-1, c));
    const std::vector<Candidate> singles = evaluate(sets, scope);
    std::vector<std::pair<double, int>> losses, gains;
    for (size_t k = 0; k < singles.size(); ++k) {
      if (!singles[k].mesh) continue;
      const double change = singles[k].objective - base[0].objective;
      if (k < references_.size()) {
        losses.emplace_back(change, references_[k]);
      } else {
        gains.emplace_back(change, insertions[k - references_.size()]);
      }
    }
    std::sort(losses.begin(), losses.end());
    std::sort(gains.begin(), gains.end());
    losses.resize(std::min(losses.size(), kRemovals));
    gains.resize(std::min(gains.size(), kInsertions));
    std::vector<std::tuple<double, int, int>> pairs;
    for (const auto& [loss, v] : losses) {
      for (const auto& [gain, c] : gains) pairs.emplace_back(loss + gain, v, c);
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.resize(std::min(pairs.size(), kPairs));
    std::vector<std::vector<int>> tries;
    for (const auto& [estimate, v, c] : pairs) tries.push_back(replaced(v, c));
    if (screening()) tries = screenedBest(tries, base[0].objective, kExchangesScored);
    const std::vector<Candidate> exchanged = evaluate(tries);
    size_t best = exchanged.size();
    for (size_t k = 0; k < exchanged.size(); ++k) {
      if (exchanged[k].objective < (best < exchanged.size() ? exchanged[best].objective : objective_)) best = k;
    }
    if (best == exchanged.size()) return std::nullopt;
    const auto [removed, added] = exchangedPair(exchanged[best]);
    accept(removed, exchanged[best]);
    return std::make_pair(removed, added);
  }

  // The reference an exchange took out and the sample it put in.
  std::pair<int, int> exchangedPair(const Candidate& candidate) const {
    std::vector<int> removed;
    std::set_difference(references_.begin(), references_.end(), candidate.references.begin(),
                        candidate.references.end(), std::back_inserter(removed));
    TRIWALK_CHECK(removed.size() == 1, "an exchange takes out one reference");
    return {removed[0], candidate.placement};
  }

  // Makes a candidate the selection, logged as moving reference `moved`.
  void accept(int moved, const Candidate& candidate) {
    Collapse move;
    move.first = moved;
    move.placement = candidate.placement;
    move.kind = PlacementKind::Relocation;
    move.cost = candidate.objective;
    move.error = candidate.objective;
    // The log starts from the given mesh, not from the Delaunay mesh the
    // moves start from.
    const ViewMesh& logged = result_.moves.empty() ? start_ : mesh_;
    move.removed = without(logged.triangles(), candidate.mesh->triangles());
    move.added = without(candidate.mesh->triangles(), logged.triangles());
    result_.moves.push_back(std::move(move));
    references_ = candidate.references;
    mesh_ = *candidate.mesh;
    objective_ = candidate.objective;
    screenedObjective_.reset();
  }

  std::span<const glm::dvec2> positions_;
  const RefinementOptions& options_;
  ObjectiveEvaluator evaluator_;
  ViewMesh mesh_;
  std::vector<int> references_;  // sorted
  double objective_ = 0.0;
  std::optional<double> screenedObjective_;  // of references_, when screening asked for it
  RefinementResult& result_;
  ViewMesh start_;  // the given mesh
  double startObjective_ = 0.0;
};

}  // namespace

RefinementResult refineSelection(std::span<const glm::dvec2> positions, const std::vector<Triangle>& current,
                                 ReconstructionErrorSource& errors, const RefinementOptions& options,
                                 ProgressReporter* progress) {
  TRIWALK_CHECK(!current.empty(), "refining a selection needs its triangles");
  RefinementResult result;
  result.radius = options.radius.value_or(neighbourhoodRadius(positions));
  Refinement refinement(positions, current, errors, options, result);
  result.objectiveBefore = refinement.objective();
  if (result.radius > 0.0) {
    refinement.startFromDelaunay();
    refinement.refine(options.maxExchanges.value_or(refinement.mesh().vertexCount()), progress);
    refinement.keepTheBetter();
  }
  result.objectiveAfter = refinement.objective();
  result.triangles = refinement.mesh().triangles();
  return result;
}

}  // namespace triwalk
