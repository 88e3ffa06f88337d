#include "core/selection/selection_refinement.h"

#include "core/geometry/line_of_sight_table.h"
#include "core/geometry/view_mesh.h"
#include "core/selection/sample_pricing.h"
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

// The variance of values about their group's mean, pooled over groups
// (degrees of freedom: values minus groups); +inf with too few values to tell.
double sampleVariance(const std::map<int, std::vector<double>>& groups) {
  double squares = 0.0;
  size_t count = 0;
  for (const auto& [group, values] : groups) {
    double mean = 0.0;
    for (double v : values) mean += v;
    mean /= double(values.size());
    for (double v : values) squares += (v - mean) * (v - mean);
    count += values.size() - 1;
  }
  return count > 0 ? squares / double(count) : std::numeric_limits<double>::infinity();
}

// Which triangle reconstructs each dense sample that is not a reference.
class ObjectiveEvaluator {
public:
  ObjectiveEvaluator(std::span<const glm::dvec2> positions, std::span<const double> weights,
                     const WalkableRegion* region, ReconstructionErrorSource& errors, RefinementResult& result)
      : positions_(positions.begin(), positions.end()), weights_(weights.begin(), weights.end()), region_(region),
        sight_(positions, region), errors_(errors), result_(result) {}

  // Every sample's, or only those of the screened subset; triangleIds, if
  // given, receives the index in mesh of each one's triangle.
  std::vector<SampleReconstruction> assignments(const ViewMesh& mesh, bool screenedOnly = false,
                                                std::vector<int>* triangleIds = nullptr) const {
    std::vector<SampleReconstruction> requests;
    const std::vector<int>& references = mesh.vertices();
    int hint = -1;
    for (int i = 0; i < int(positions_.size()); ++i) {
      if (screenedOnly && !screened_[size_t(i)]) continue;
      if (std::binary_search(references.begin(), references.end(), i)) continue;
      if (weightOf(i) == 0.0) continue;  // not judged
      hint = mesh.locate(positions_[size_t(i)], hint, [&](int reference) { return sight_.sees(reference, i); });
      requests.push_back({sortedTriangle(mesh.triangles()[size_t(hint)]), i});
      if (triangleIds) triangleIds->push_back(hint);
    }
    return requests;
  }

  // Makes mesh, whose errors are computed, the selection that candidates
  // are priced against: which triangle serves each sample there, and the
  // weighted sum of their errors.
  void setCurrent(const ViewMesh& mesh) {
    currentServing_.assign(positions_.size(), kReference);
    currentSum_ = currentWeight_ = 0.0;
    for (const SampleReconstruction& request : assignments(mesh)) {
      currentServing_[size_t(request.destination)] = request.references;
      currentSum_ += weightOf(request.destination) * known_.at(request);
      currentWeight_ += weightOf(request.destination);
    }
  }

  // A candidate mesh priced against the current selection: its samples
  // whose serving triangle changes are priced on a stratified subset of at
  // most `limit` (by their new triangle); the references it frees are
  // always priced, the samples it makes references leave the mean. Exact
  // (every changed sample priced): the whole assignment is scored instead.
  struct PricedChange {
    std::vector<SampleReconstruction> assignment;  // every sample's
    bool exact = true;
    std::vector<SampleReconstruction> priced;  // when not exact: the errors that price it
    std::vector<double> scales;                // per priced: the weight it stands for over its own
    std::vector<int> strata;                   // per priced: its new triangle (-1: a freed reference, exact)
    std::vector<int> stratumSizes;             // per priced: how many changed samples that triangle serves
    std::vector<int> leaving;                  // samples that become references
  };
  PricedChange pricedChange(const ViewMesh& mesh, size_t limit) const {
    PricedChange change;
    std::vector<int> triangleIds;
    change.assignment = assignments(mesh, false, &triangleIds);
    std::vector<int> changed, strata;
    std::vector<size_t> positionInAssignment;
    for (size_t j = 0; j < change.assignment.size(); ++j) {
      const SampleReconstruction& request = change.assignment[j];
      const Triangle& now = currentServing_[size_t(request.destination)];
      if (now == kReference) {
        change.priced.push_back(request);
        change.scales.push_back(1.0);
        change.strata.push_back(-1);
        change.stratumSizes.push_back(1);
      } else if (now != request.references) {
        changed.push_back(request.destination);
        strata.push_back(triangleIds[j]);
        positionInAssignment.push_back(j);
      }
    }
    const std::vector<PricedSample> chosen =
        stratifiedPricing(changed, strata, limit, [this](int sample) { return weightOf(sample); });
    change.exact = chosen.size() == changed.size();
    if (change.exact) return change;
    std::map<int, int> sizes;
    for (int stratum : strata) ++sizes[stratum];
    for (const PricedSample& sample : chosen) {
      const int stratum = strata[size_t(sample.index)];
      change.priced.push_back(change.assignment[positionInAssignment[size_t(sample.index)]]);
      change.scales.push_back(sample.scale);
      change.strata.push_back(stratum);
      change.stratumSizes.push_back(sizes[stratum]);
    }
    for (int v : mesh.vertices()) {
      if (currentServing_[size_t(v)] != kReference) change.leaving.push_back(v);
    }
    return change;
  }

  // The estimated objective of a priced change whose errors are computed,
  // and its standard error: each new triangle's total change is estimated
  // from a simple random sample of its changed samples, whose variance
  // (with the finite-population correction) the sample's own spread gives;
  // a triangle priced on one sample borrows the spread of all of them.
  struct Estimate {
    double objective = 0.0;
    double standardError = 0.0;
  };
  Estimate estimate(const PricedChange& change) const {
    double sum = currentSum_, weight = currentWeight_;
    std::map<int, std::vector<double>> changes;    // per new triangle: w (after - before) of its priced samples
    std::map<int, std::pair<double, int>> strata;  // per new triangle: (scale, changed samples)
    for (size_t k = 0; k < change.priced.size(); ++k) {
      const SampleReconstruction& request = change.priced[k];
      const Triangle& before = currentServing_[size_t(request.destination)];
      const double w = weightOf(request.destination);
      if (before == kReference) {
        sum += w * known_.at(request);
        weight += w;
      } else {
        const double difference = w * (known_.at(request) - known_.at({before, request.destination}));
        sum += change.scales[k] * difference;
        changes[change.strata[k]].push_back(difference);
        strata[change.strata[k]] = {change.scales[k], change.stratumSizes[k]};
      }
    }
    for (int v : change.leaving) {
      sum -= weightOf(v) * known_.at({currentServing_[size_t(v)], v});
      weight -= weightOf(v);
    }
    if (weight <= 0.0) return {0.0, 0.0};
    const double pooled = sampleVariance(changes);
    double variance = 0.0;
    for (const auto& [stratum, values] : changes) {
      const auto [scale, size] = strata.at(stratum);
      const double n = double(values.size());
      const double unsampled = 1.0 - n / double(size);
      if (unsampled <= 0.0) continue;  // every changed sample of the triangle priced: exact
      const double spread = values.size() > 1 ? sampleVariance({{stratum, values}}) : pooled;
      variance += scale * scale * n * spread * unsampled;
    }
    return {sum / weight, std::sqrt(variance) / weight};
  }

  // Computes, in one parallel batch, every error the given assignments
  // need that is not cached yet; with progress, in chunks that advance it
  // and stop on Ctrl-C between them.
  void compute(const std::vector<std::vector<SampleReconstruction>>& batches, ProgressReporter* progress = nullptr) {
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
    const std::vector<double> values =
        computeInChunks(std::span<const SampleReconstruction>(requests), progress,
                        [this](std::span<const SampleReconstruction> chunk, std::span<double> computed) {
                          errors_.computeReconstructionErrors(chunk, computed);
                        });
    for (size_t i = 0; i < requests.size(); ++i) known_.emplace(requests[i], values[i]);
    result_.errorsComputed += requests.size();
  }

  double mean(const std::vector<SampleReconstruction>& assignment) const {
    double sum = 0.0, weightSum = 0.0;
    for (const SampleReconstruction& request : assignment) {
      const double weight = weightOf(request.destination);
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
  static constexpr Triangle kReference = {-1, -1, -1};  // in currentServing_: a reference, served by none

  double weightOf(int sample) const { return weights_.empty() ? 1.0 : weights_[size_t(sample)]; }

  std::vector<glm::dvec2> positions_;
  std::vector<double> weights_;
  const WalkableRegion* region_;
  LineOfSightTable sight_;  // asked by ViewMesh::locate for samples outside every triangle
  ReconstructionErrorSource& errors_;
  RefinementResult& result_;
  std::map<SampleReconstruction, double> known_;
  std::vector<char> screened_;
  std::vector<Triangle> currentServing_;  // per sample, in the current selection
  double currentSum_ = 0.0, currentWeight_ = 0.0;
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
    evaluator_.setCurrent(mesh_);
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
    evaluator_.setCurrent(mesh_);
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
    evaluator_.setCurrent(mesh_);
  }

  // Local moves until none helps; then, as long as an exchange helps (at
  // most maxExchanges), the exchange and local moves around it again. So
  // the result is never worse than local moves alone, and no single move
  // of either kind improves it.
  void refine(int maxExchanges, ProgressReporter* progress) {
    std::set<int> movable;
    for (int r : references_) {
      if (!isFrozen(r)) movable.insert(r);
    }
    moveLocally(movable, progress);
    while (result_.exchanges < maxExchanges) {
      throwIfInterrupted();
      const ViewMesh before = mesh_;
      const uint64_t computedBefore = result_.errorsComputed;
      const std::optional<std::pair<int, int>> exchanged = bestExchange(progress);
      result_.exchangeSearchErrors += result_.errorsComputed - computedBefore;
      if (!exchanged) break;
      ++result_.exchanges;
      const auto [removed, added] = *exchanged;
      std::set<int> flagged = {added};
      for (int v : neighboursOf(before, removed)) flagged.insert(v);
      for (int v : neighboursOf(mesh_, added)) flagged.insert(v);
      std::erase_if(flagged, [&](int v) {
        return isFrozen(v) || !std::binary_search(references_.begin(), references_.end(), v);
      });
      moveLocally(flagged, progress);
    }
  }

  // Greedy insertion: while there are fewer than count references, the
  // free sample whose insertion gives the lowest objective joins (the lower
  // index on a tie), scored as the exchange search scores its insertions.
  // Each joins even where the objective would rise: the count is asked for.
  // inserted receives them in order, objectives the objective after each.
  void insertUntil(int count, std::vector<int>& inserted, std::vector<double>& objectives, ProgressReporter* progress) {
    while (int(references_.size()) < count) {
      throwIfInterrupted();
      std::vector<int> insertions;
      std::vector<std::vector<int>> additions;
      for (int c = 0; c < int(positions_.size()); ++c) {
        if (isFrozen(c) || std::binary_search(references_.begin(), references_.end(), c)) continue;
        insertions.push_back(c);
        additions.push_back(replaced(-1, c));
      }
      const std::vector<std::pair<double, int>> lowest =
          lowestChanges(additions, insertions, objective_, 1, Scope::AllSamples, nullptr);
      if (lowest.empty()) return;  // no insertion keeps a triangle in the region
      const int added = lowest[0].second;
      adopt(evaluate({replaced(-1, added)})[0]);
      inserted.push_back(added);
      objectives.push_back(objective_);
      if (progress) {
        char status[64];
        std::snprintf(status, sizeof status, "mean error %.4f", objective_);
        progress->setStatus(status);
        progress->advance();
      }
    }
  }

private:
  bool isFrozen(int sample) const { return !options_.frozen.empty() && options_.frozen[size_t(sample)]; }

  // Local moves within radius, pass after pass over the flagged references
  // (at most maxPasses).
  void moveLocally(std::set<int> flagged, ProgressReporter* progress) {
    int passes = 0;
    while (!flagged.empty() && passes < options_.maxPasses) {
      ++passes;
      ++result_.passes;
      const std::vector<int> examine(flagged.begin(), flagged.end());
      flagged.clear();
      if (progress) progress->setTotal(progress->done() + examine.size(), "pass " + std::to_string(result_.passes));
      for (int moving : examine) {
        throwIfInterrupted();
        if (progress) progress->advance();
        if (!std::binary_search(references_.begin(), references_.end(), moving))
          continue;  // moved away earlier in this pass
        std::vector<std::vector<int>> tries;
        for (int c = 0; c < int(positions_.size()); ++c) {
          if (isFrozen(c) || std::binary_search(references_.begin(), references_.end(), c)) continue;
          if (glm::length(positions_[size_t(c)] - positions_[size_t(moving)]) > result_.radius) continue;
          tries.push_back(replaced(moving, c));
        }
        const std::optional<Candidate> best = bestBelowNow(tries, Moves::Local);
        if (!best) continue;
        const int placement = best->placement;
        for (int v : neighboursOf(mesh_, moving)) flagged.insert(v);
        for (int v : neighboursOf(*best->mesh, placement)) flagged.insert(v);
        flagged.insert(placement);
        std::erase_if(flagged, [&](int v) { return isFrozen(v); });
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
    bool exact = true;           // objective over every sample (not screened, not priced on a subset)
    double standardError = 0.0;  // of a priced objective
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

  enum class Scope { AllSamples, Screened, Priced };
  bool screening() const { return options_.screenedShare > 0.0; }
  bool pricing() const { return options_.pricedSamples > 0; }

  // The screened objective of the references, computed once per selection
  // (the errors come from the cache, the triangulation would not).
  double screenedObjective() {
    if (!screenedObjective_) screenedObjective_ = evaluate({references_}, Scope::Screened)[0].objective;
    return *screenedObjective_;
  }

  // Of reference sets, the `keep` whose screened objective is lowest and
  // below `below`, in the order given (so ties still go to the earlier).
  std::vector<std::vector<int>> screenedBest(const std::vector<std::vector<int>>& sets, double below, size_t keep) {
    std::vector<std::vector<int>> kept;
    for (Candidate& candidate : best(evaluate(sets, Scope::Screened), below, keep)) {
      kept.push_back(std::move(candidate.references));
    }
    return kept;
  }

  // Of reference sets, the one whose exact objective is lowest and below
  // the current one (ties: the earlier), or none. Screening ranks the sets
  // first and scores only the best few exactly; pricing (local moves;
  // an exchange search prices its singles, not its pairs) scores exactly
  // those its estimate cannot rule out.
  enum class Moves { Local, Exchanges };
  std::optional<Candidate> bestBelowNow(const std::vector<std::vector<int>>& sets, Moves moves,
                                        ProgressReporter* progress = nullptr) {
    std::vector<Candidate> candidates;
    if (screening()) {
      candidates =
          evaluate(screenedBest(sets, screenedObjective(), moves == Moves::Local ? kMovesScored : kExchangesScored));
    } else if (pricing() && moves == Moves::Local) {
      candidates = exactly(plausiblyBelowNow(repriced(plausiblyBelowNow(evaluate(sets, Scope::Priced)))));
    } else {
      candidates = evaluate(sets, Scope::AllSamples, progress);
    }
    std::optional<Candidate> lowest;
    for (Candidate& candidate : candidates) {
      if (candidate.objective < (lowest ? lowest->objective : objective_)) lowest = std::move(candidate);
    }
    return lowest;
  }

  // Of candidates, the `keep` whose objective is lowest and below `below`,
  // in the order given.
  static std::vector<Candidate> best(std::vector<Candidate> candidates, double below, size_t keep) {
    std::vector<std::pair<double, size_t>> ranked;
    for (size_t k = 0; k < candidates.size(); ++k) {
      if (candidates[k].objective < below) ranked.emplace_back(candidates[k].objective, k);
    }
    std::sort(ranked.begin(), ranked.end());
    ranked.resize(std::min(ranked.size(), keep));
    std::sort(ranked.begin(), ranked.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
    std::vector<Candidate> kept;
    for (const auto& [objective, k] : ranked) kept.push_back(std::move(candidates[k]));
    return kept;
  }

  // How many standard errors a priced candidate's estimate may be off
  // before it is ruled out: a one-sided 2.3% chance of missing a better one.
  static constexpr double kPlausible = 2.0;

  // Of priced candidates, those that may be below the current objective:
  // their estimate is less than kPlausible standard errors above it. So a
  // candidate is scored exactly unless its sample makes it clearly worse,
  // and how many are depends on how close they come, not on a count.
  std::vector<Candidate> plausiblyBelowNow(std::vector<Candidate> candidates) const {
    std::erase_if(candidates, [&](const Candidate& candidate) {
      return !(candidate.objective - kPlausible * candidate.standardError < objective_);
    });
    return candidates;
  }

  // Of candidates, priced or exact, those that cannot be among the `keep`
  // lowest lose their mesh (they are ranked no further): a candidate whose
  // estimate is more than kPlausible standard errors above the keep-th
  // lowest of (estimate + kPlausible standard errors). The `keep` lowest
  // exact objectives are kept unless a sample puts one that far off.
  static void ruleOutAllButLowest(std::vector<Candidate>& candidates, size_t keep) {
    std::vector<double> upper;
    for (const Candidate& candidate : candidates) {
      if (candidate.mesh) upper.push_back(candidate.objective + kPlausible * candidate.standardError);
    }
    if (keep == 0 || upper.size() <= keep) return;
    std::nth_element(upper.begin(), upper.begin() + std::ptrdiff_t(keep - 1), upper.end());
    const double bound = upper[keep - 1];
    for (Candidate& candidate : candidates) {
      if (candidate.mesh && candidate.objective - kPlausible * candidate.standardError > bound) candidate.mesh.reset();
    }
  }

  // The candidates with their exact objectives (those with a mesh priced
  // on a subset scored again over every sample), in the same order.
  std::vector<Candidate> exactly(std::vector<Candidate> candidates, ProgressReporter* progress = nullptr) {
    std::vector<size_t> inexact;
    for (size_t k = 0; k < candidates.size(); ++k) {
      if (candidates[k].mesh && !candidates[k].exact) inexact.push_back(k);
    }
    scoreExactly(candidates, inexact, progress);
    return candidates;
  }

  // The priced candidates priced again on options_.repricing times as many
  // of the samples they change, in the same order. The subsets are the
  // samples of lowest fixed rank in each new triangle, so the first subset
  // is part of the second and its errors count again: a candidate that the
  // closer look rules out costs that many times its first price, not
  // every sample it changes.
  std::vector<Candidate> repriced(std::vector<Candidate> candidates, ProgressReporter* progress = nullptr) {
    if (options_.repricing <= 1) return candidates;
    std::vector<size_t> inexact;
    std::vector<std::vector<int>> sets;
    for (size_t k = 0; k < candidates.size(); ++k) {
      if (candidates[k].mesh && !candidates[k].exact) {
        inexact.push_back(k);
        sets.push_back(candidates[k].references);
      }
    }
    std::vector<Candidate> again = evaluate(sets, Scope::Priced, progress, options_.repricing * options_.pricedSamples);
    for (size_t i = 0; i < inexact.size(); ++i) candidates[inexact[i]] = std::move(again[i]);
    return candidates;
  }

  // Scores the candidates at the given positions over every sample, in place.
  void scoreExactly(std::vector<Candidate>& candidates, std::span<const size_t> at, ProgressReporter* progress) {
    std::vector<std::vector<int>> sets;
    for (size_t k : at) sets.push_back(candidates[k].references);
    std::vector<Candidate> scored = evaluate(sets, Scope::AllSamples, progress);
    for (size_t i = 0; i < at.size(); ++i) candidates[at[i]] = std::move(scored[i]);
  }

  // Of priced candidates, those that may be among the `keep` lowest scored
  // exactly, the others ruled out (ruleOutAllButLowest), in two rounds:
  // first the `keep` lowest estimates, whose exact objectives then tighten
  // the bound the others are ruled out by.
  void scoreLowestExactly(std::vector<Candidate>& candidates, size_t keep, ProgressReporter* progress) {
    ruleOutAllButLowest(candidates, keep);
    std::vector<std::pair<double, size_t>> inexact;
    for (size_t k = 0; k < candidates.size(); ++k) {
      if (candidates[k].mesh && !candidates[k].exact) inexact.emplace_back(candidates[k].objective, k);
    }
    std::sort(inexact.begin(), inexact.end());
    inexact.resize(std::min(inexact.size(), keep));
    std::vector<size_t> first;
    for (const auto& [estimate, k] : inexact) first.push_back(k);
    std::sort(first.begin(), first.end());
    scoreExactly(candidates, first, progress);
    ruleOutAllButLowest(candidates, keep);
    candidates = repriced(std::move(candidates), progress);
    ruleOutAllButLowest(candidates, keep);
    candidates = exactly(std::move(candidates), progress);
  }

  // Triangulates and scores reference sets, the errors they need in one
  // parallel batch; results in the order given.
  std::vector<Candidate> evaluate(const std::vector<std::vector<int>>& sets, Scope scope = Scope::AllSamples,
                                  ProgressReporter* progress = nullptr, int pricedSamples = 0) {
    const size_t pricedLimit = size_t(pricedSamples > 0 ? pricedSamples : options_.pricedSamples);
    std::vector<Candidate> candidates(sets.size());
    std::vector<std::vector<SampleReconstruction>> requests(sets.size());
    std::vector<ObjectiveEvaluator::PricedChange> changes(scope == Scope::Priced ? sets.size() : 0);
    tbb::parallel_for(size_t(0), sets.size(), [&](size_t k) {
      Candidate& candidate = candidates[k];
      candidate.references = sets[k];
      for (int r : sets[k]) {
        if (!std::binary_search(references_.begin(), references_.end(), r)) candidate.placement = r;
      }
      candidate.mesh = evaluator_.triangulate(sets[k]);
      if (!candidate.mesh) return;
      if (scope != Scope::Priced) {
        requests[k] = evaluator_.assignments(*candidate.mesh, scope == Scope::Screened);
        candidate.exact = scope == Scope::AllSamples;
        return;
      }
      changes[k] = evaluator_.pricedChange(*candidate.mesh, pricedLimit);
      candidate.exact = changes[k].exact;
      requests[k] = candidate.exact ? std::move(changes[k].assignment) : changes[k].priced;
    });
    evaluator_.compute(requests, progress);
    for (size_t k = 0; k < sets.size(); ++k) {
      if (!candidates[k].mesh) continue;
      if (scope == Scope::Priced && !candidates[k].exact) {
        const ObjectiveEvaluator::Estimate estimate = evaluator_.estimate(changes[k]);
        candidates[k].objective = estimate.objective;
        candidates[k].standardError = estimate.standardError;
      } else {
        candidates[k].objective = evaluator_.mean(requests[k]);
      }
    }
    return candidates;
  }

  // The best exchange, made if it lowers the objective; its (reference,
  // sample), or nothing. Every single removal and insertion is scored, the
  // pairs of the lowest of each are ranked by the sum of their changes, and
  // the best pairs are scored exactly. Losses and gains are measured
  // against the Delaunay mesh of the references, which the first exchange
  // replaces the decimated mesh with.
  std::optional<std::pair<int, int>> bestExchange(ProgressReporter* progress) {
    constexpr size_t kRemovals = 8, kInsertions = 16, kPairs = 16;
    std::optional<ProgressReporter> searching;
    if (progress) searching.emplace("refine: search exchanges, errors", 0, progress->quiet());
    ProgressReporter* errorsProgress = searching ? &*searching : nullptr;
    const Scope scope = screening() ? Scope::Screened : Scope::AllSamples;
    const std::vector<Candidate> base = evaluate({references_}, scope);
    if (!base[0].mesh) return std::nullopt;
    std::vector<std::vector<int>> removals, additions;
    std::vector<int> removable;
    for (int v : references_) {
      if (!isFrozen(v)) removable.push_back(v), removals.push_back(replaced(v, -1));
    }
    std::vector<int> insertions = exchangeCandidates(positions_, references_);
    std::erase_if(insertions, [&](int c) { return isFrozen(c); });
    for (int c : insertions) additions.push_back(replaced(-1, c));
    if (searching) {
      searching->setStatus(std::to_string(removals.size()) + " removals, " + std::to_string(additions.size()) +
                           " insertions");
    }
    const std::vector<std::pair<double, int>> losses =
        lowestChanges(removals, removable, base[0].objective, kRemovals, scope, errorsProgress);
    const std::vector<std::pair<double, int>> gains =
        lowestChanges(additions, insertions, base[0].objective, kInsertions, scope, errorsProgress);
    std::vector<std::tuple<double, int, int>> pairs;
    for (const auto& [loss, v] : losses) {
      for (const auto& [gain, c] : gains) pairs.emplace_back(loss + gain, v, c);
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.resize(std::min(pairs.size(), kPairs));
    std::vector<std::vector<int>> tries;
    for (const auto& [estimate, v, c] : pairs) tries.push_back(replaced(v, c));
    const std::optional<Candidate> exchanged = bestBelowNow(tries, Moves::Exchanges, errorsProgress);
    if (!exchanged) return std::nullopt;
    const auto [removed, added] = exchangedPair(*exchanged);
    accept(removed, *exchanged);
    return std::make_pair(removed, added);
  }

  // Of single changes (one reference removed, or one sample added; label:
  // which), the `keep` lowest changes of the objective against `base`,
  // lowest first (ties: the lower label). Priced, unless screening: every
  // single is estimated, and only those that may be among the `keep`
  // lowest are scored exactly, so the exchange search ranks on exact
  // changes like the unpriced one unless a sample puts a single two
  // standard errors off. Most insertions change hundreds of samples at
  // large captures and are clearly not among the lowest.
  std::vector<std::pair<double, int>> lowestChanges(const std::vector<std::vector<int>>& singles,
                                                    std::span<const int> labels, double base, size_t keep, Scope scope,
                                                    ProgressReporter* progress) {
    std::vector<Candidate> scored;
    if (scope == Scope::AllSamples && pricing()) {
      scored = evaluate(singles, Scope::Priced, progress);
      scoreLowestExactly(scored, keep, progress);
    } else {
      scored = evaluate(singles, scope, progress);
    }
    std::vector<std::pair<double, int>> changes;
    for (size_t k = 0; k < scored.size(); ++k) {
      if (scored[k].mesh) changes.emplace_back(scored[k].objective - base, labels[k]);
    }
    std::sort(changes.begin(), changes.end());
    changes.resize(std::min(changes.size(), keep));
    return changes;
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
    adopt(candidate);
  }

  // Makes a candidate the selection.
  void adopt(const Candidate& candidate) {
    references_ = candidate.references;
    mesh_ = *candidate.mesh;
    objective_ = candidate.objective;
    screenedObjective_.reset();
    evaluator_.setCurrent(mesh_);
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

InsertionResult insertGreedily(std::span<const glm::dvec2> positions, std::span<const int> start, int count,
                               ReconstructionErrorSource& errors, const RefinementOptions& options,
                               ProgressReporter* progress) {
  const std::optional<ViewMesh> startMesh = ViewMesh::tryDelaunay(
      std::vector<glm::dvec2>(positions.begin(), positions.end()), start, options.region);
  TRIWALK_CHECK(startMesh && startMesh->vertexCount() == int(start.size()),
                "greedy insertion starts from samples that are all views of triangles in the region");
  RefinementResult statistics;
  Refinement insertion(positions, startMesh->triangles(), errors, options, statistics);
  InsertionResult result;
  result.objectiveBefore = insertion.objective();
  insertion.insertUntil(count, result.inserted, result.objectives, progress);
  result.triangles = insertion.mesh().triangles();
  result.errorsComputed = statistics.errorsComputed;
  return result;
}

}  // namespace triwalk
