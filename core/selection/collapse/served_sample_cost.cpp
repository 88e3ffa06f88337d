#include "core/selection/collapse/served_sample_cost.h"

#include "core/support/progress.h"

#include <algorithm>
#include <limits>
#include <span>
#include <unordered_set>

namespace triwalk {

ServedSampleCost::ServedSampleCost(const ViewMesh& dense, const CollapseMesh& mesh, ReconstructionErrorSource& errors,
                                   std::vector<double> weights, int pricedSamples, DecimationStatistics& statistics,
                                   ProgressReporter* progress)
    : mesh_(mesh),
      errors_(errors),
      weights_(std::move(weights)),
      pricedSamples_(pricedSamples),
      statistics_(statistics),
      sight_(mesh.positions(), mesh.region().get()) {
  const size_t samples = size_t(mesh.sampleCount());
  home_.assign(samples, -1);
  homeError_.assign(samples, 0.0);
  homeRank_.assign(samples, ServingRank{});
  served_.assign(size_t(mesh.triangleIds()), {});
  std::vector<SampleReconstruction> requests;
  int hint = -1;
  for (int s = 0; s < int(samples); ++s) {
    if (mesh.isVertex(s)) continue;
    hint = dense.locate(mesh.position(s), hint);
    home_[size_t(s)] = hint;
    homeRank_[size_t(s)] = servingRank(mesh.triangle(hint), s);
    if (homeRank_[size_t(s)].distance > 0.0) outside_.insert(s);
    served_[size_t(hint)].push_back(s);
    requests.push_back({sortedTriangle(mesh.triangle(hint)), s});
  }
  ensureSampleErrors(requests, progress);
  for (const SampleReconstruction& request : requests) {
    homeError_[size_t(request.destination)] = sampleError(request.references, request.destination);
  }
}

// The samples the changed triangles will serve, and where each goes:
// the samples the removed triangles served, the freed vertices (not the
// placement, which becomes a reference), and samples outside the mesh
// that a new triangle now serves better (ties broken by the rank's vertex
// triple, as eval does).
void ServedSampleCost::prepare(int a, int b, CollapsePlan& plan) const {
  ServedChange& change = plan.served;
  change.samples.clear();
  change.servedBy.clear();
  for (int t : plan.removed)
    change.samples.insert(change.samples.end(), served_[size_t(t)].begin(), served_[size_t(t)].end());
  for (int freed : {a, b}) {
    if (freed != plan.placement) change.samples.push_back(freed);
  }
  auto bestAdded = [&](int sample, ServingRank& rank) {
    int home = -1;
    rank = {true, std::numeric_limits<double>::infinity(), {}};
    for (size_t k = 0; k < plan.added.size() && rank.distance > 0.0; ++k) {
      const ServingRank r = servingRank(plan.added[k], sample);
      if (r < rank) rank = r, home = int(k);
    }
    return home;
  };
  for (int sample : outside_) {
    if (std::binary_search(plan.removed.begin(), plan.removed.end(), home_[size_t(sample)])) continue;  // listed above
    ServingRank rank;
    bestAdded(sample, rank);
    if (rank < homeRank_[size_t(sample)]) change.samples.push_back(sample);
  }
  change.samples.erase(std::remove(change.samples.begin(), change.samples.end(), plan.placement), change.samples.end());
  std::sort(change.samples.begin(), change.samples.end());
  change.rank.clear();
  for (int sample : change.samples) {
    ServingRank rank;
    int home = bestAdded(sample, rank);
    if (rank.distance > 0.0) {
      // Outside the new triangles: an existing triangle may serve it better.
      for (int t = 0; t < mesh_.triangleIds(); ++t) {
        if (!mesh_.alive(t) || std::binary_search(plan.removed.begin(), plan.removed.end(), t)) continue;
        const ServingRank r = servingRank(mesh_.triangle(t), sample);
        if (r < rank) rank = r, home = -1 - t;
      }
    }
    change.servedBy.push_back(home);
    change.rank.push_back(rank);
  }
  choosePricedSamples(a, b, plan);
}

// Which served samples price the collapse, and how much each stands for:
// all of them, or, past pricedSamples, the freed vertices and, from the
// others, a share of each new serving triangle's samples (its share of the
// others, at least one): those of lowest fixed rank, each standing for
// its triangle's weight over theirs. Stratified by triangle because a
// sample's error depends mostly on the triangle serving it. The rank is
// the same for every plan, so the subsets of overlapping plans overlap
// (their errors are shared through the cache), and a late collapse, whose
// triangles serve hundreds of samples, costs what an early one does.
void ServedSampleCost::choosePricedSamples(int a, int b, CollapsePlan& plan) const {
  ServedChange& change = plan.served;
  change.priced.clear();
  std::vector<int> others, strata, indices;
  for (size_t i = 0; i < change.samples.size(); ++i) {
    const int sample = change.samples[i];
    if (sample == a || sample == b) {
      change.priced.push_back({int(i), 1.0});
    } else {
      others.push_back(sample);
      strata.push_back(change.servedBy[i]);
      indices.push_back(int(i));
    }
  }
  for (const PricedSample& other :
       stratifiedPricing(others, strata, size_t(pricedSamples_), [this](int s) { return weightOf(s); })) {
    change.priced.push_back({indices[size_t(other.index)], other.scale});
  }
  std::sort(change.priced.begin(), change.priced.end());
}

void ServedSampleCost::ensureErrors(const std::vector<const CollapsePlan*>& plans, ProgressReporter* progress) {
  std::vector<SampleReconstruction> requests;
  for (const CollapsePlan* plan : plans) {
    for (const PricedSample& priced : plan->served.priced) requests.push_back(request(*plan, size_t(priced.index)));
  }
  ensureSampleErrors(requests, progress);
}

// The increase of the served samples' total error (the freed vertices
// count from zero, the placement leaves the sum), and the mean error of
// the samples the new triangles serve. Sums run in sample order, so the
// result does not depend on the history that led to this mesh.
CostAndError ServedSampleCost::price(const CollapsePlan& plan) const {
  const ServedChange& change = plan.served;
  const double placementBefore = weightOf(plan.placement) * homeError_[size_t(plan.placement)];
  if (change.priced.size() == change.samples.size()) {
    double after = 0.0, before = 0.0, weightSum = 0.0;
    for (size_t i = 0; i < change.samples.size(); ++i) {
      const int sample = change.samples[i];
      const double weight = weightOf(sample);
      after += weight * sampleError(servingTriangle(plan, i), sample);
      before += weight * homeError_[size_t(sample)];
      weightSum += weight;
    }
    return {after - before - placementBefore, weightSum > 0.0 ? after / weightSum : 0.0};
  }
  // A subset priced: each priced sample's change of error (paired, since
  // a sample's error before and after are close; a freed vertex's before
  // is 0) stands for the samples it was chosen for.
  double before = 0.0, weightSum = 0.0, increase = 0.0;
  for (const int sample : change.samples) {
    const double weight = weightOf(sample);
    before += weight * homeError_[size_t(sample)];
    weightSum += weight;
  }
  for (const PricedSample& priced : change.priced) {
    const size_t i = size_t(priced.index);
    const int sample = change.samples[i];
    const double after = sampleError(servingTriangle(plan, i), sample);
    increase += priced.scale * weightOf(sample) * (after - homeError_[size_t(sample)]);
  }
  return {increase - placementBefore, weightSum > 0.0 ? (before + increase) / weightSum : 0.0};
}

// Served samples move to the new triangles; the placement is a reference
// now. If it was served by a triangle outside the collapse (on a shared
// edge), that triangle's edges must be priced again too, as must those of
// existing triangles that now serve samples outside the mesh.
std::vector<int> ServedSampleCost::follow(const CollapsePlan& plan, int firstAdded) {
  const ServedChange& change = plan.served;
  if (change.priced.size() < change.samples.size()) {  // the samples left out of the price have errors from now on
    std::vector<SampleReconstruction> requests;
    for (size_t i = 0; i < change.samples.size(); ++i) requests.push_back(request(plan, i));
    ensureSampleErrors(requests);
  }
  served_.resize(size_t(mesh_.triangleIds()));
  for (int t : plan.removed) served_[size_t(t)].clear();
  std::set<int> gained;
  int placementHome = home_[size_t(plan.placement)];
  if (placementHome >= 0) {
    auto& list = served_[size_t(placementHome)];
    list.erase(std::remove(list.begin(), list.end(), plan.placement), list.end());
    if (!mesh_.alive(placementHome)) placementHome = -1;
  }
  home_[size_t(plan.placement)] = -1;
  homeError_[size_t(plan.placement)] = 0.0;
  for (size_t i = 0; i < change.samples.size(); ++i) {
    const int sample = change.samples[i];
    const int previous = home_[size_t(sample)];
    if (previous >= 0 && mesh_.alive(previous)) {  // an outside sample a new triangle is nearer to
      auto& list = served_[size_t(previous)];
      list.erase(std::remove(list.begin(), list.end(), sample), list.end());
    }
    const int home = change.servedBy[i] >= 0 ? firstAdded + change.servedBy[i] : -1 - change.servedBy[i];
    home_[size_t(sample)] = home;
    homeError_[size_t(sample)] = sampleError(sortedTriangle(servingTriangle(plan, i)), sample);
    homeRank_[size_t(sample)] = change.rank[i];
    served_[size_t(home)].push_back(sample);
    if (home < firstAdded) gained.insert(home);
    if (change.rank[i].distance > 0.0) {
      outside_.insert(sample);
    } else {
      outside_.erase(sample);
    }
  }
  outside_.erase(plan.placement);
  if (placementHome >= 0) gained.insert(placementHome);
  return {gained.begin(), gained.end()};
}

double ServedSampleCost::meanError() const {
  double sum = 0.0, weightSum = 0.0;
  for (size_t s = 0; s < home_.size(); ++s) {
    if (home_[s] < 0) continue;
    sum += weightOf(int(s)) * homeError_[s];
    weightSum += weightOf(int(s));
  }
  return weightSum > 0.0 ? sum / weightSum : 0.0;
}

const Triangle& ServedSampleCost::servingTriangle(const CollapsePlan& plan, size_t i) const {
  const int by = plan.served.servedBy[i];
  return by >= 0 ? plan.added[size_t(by)] : mesh_.triangle(-1 - by);
}

// As ViewMesh::locate ranks triangles, from the samples' own positions.
ServingRank ServedSampleCost::servingRank(const Triangle& triangle, int sample) const {
  return rankTriangle(triangle, distanceToTriangle(mesh_.positions(), triangle, mesh_.position(sample)),
                      [&](int v) { return sight_.sees(v, sample); });
}

SampleReconstruction ServedSampleCost::request(const CollapsePlan& plan, size_t i) const {
  return {sortedTriangle(servingTriangle(plan, i)), plan.served.samples[i]};
}

void ServedSampleCost::ensureSampleErrors(const std::vector<SampleReconstruction>& requests,
                                          ProgressReporter* progress) {
  std::vector<SampleReconstruction> missing;
  std::unordered_set<SampleKey, SampleKeyHash> queued;
  for (const SampleReconstruction& request : requests) {
    const SampleKey key{triangleKey(request.references), request.destination};
    if (cache_.count(key) || !queued.insert(key).second) {
      ++statistics_.cacheHits;
      continue;
    }
    missing.push_back(request);
  }
  if (missing.empty()) return;
  const std::vector<double> computed =
      computeInChunks(std::span<const SampleReconstruction>(missing), progress,
                      [&](std::span<const SampleReconstruction> batch, std::span<double> batchErrors) {
                        errors_.computeReconstructionErrors(batch, batchErrors);
                      });
  for (size_t i = 0; i < missing.size(); ++i) {
    cache_[SampleKey{triangleKey(missing[i].references), missing[i].destination}] = computed[i];
  }
  statistics_.errorsComputed += missing.size();
}

double ServedSampleCost::sampleError(const Triangle& triangle, int sample) const {
  return cache_.at(SampleKey{triangleKey(triangle), sample});
}

}  // namespace triwalk
