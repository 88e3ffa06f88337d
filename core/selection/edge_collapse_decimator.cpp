#include "core/selection/edge_collapse_decimator.h"

#include "core/selection/collapse/centroid_cost.h"
#include "core/selection/collapse/served_sample_cost.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace triwalk {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

const char* collapseCostName(CollapseCost cost) {
  return cost == CollapseCost::ServedSamples ? "served-samples" : "centroid";
}

CollapseCost parseCollapseCost(const std::string& name) {
  if (name == "served-samples") return CollapseCost::ServedSamples;
  if (name == "centroid") return CollapseCost::Centroid;
  throw InputError("cost", "unknown cost '" + name + "' (use served-samples or centroid)");
}

const char* recostingName(bool lazyRecosting) { return lazyRecosting ? "lazy" : "eager"; }

bool parseLazyRecosting(const std::string& name) {
  if (name == "lazy" || name == "eager") return name == "lazy";
  throw InputError("recosting", "unknown recosting '" + name + "' (use lazy or eager)");
}

const char* stopReasonName(StopReason reason) {
  switch (reason) {
    case StopReason::None: return "not stopped";
    case StopReason::MaxError: return "every collapse left would exceed the error threshold";
    case StopReason::TargetReached: return "reached the target sample count";
    case StopReason::NoValidCollapse: return "no valid collapse is left";
    case StopReason::Interrupted: return "interrupted";
  }
  return "?";
}

EdgeCollapseDecimator::EdgeCollapseDecimator(const ViewMesh& mesh, DecimationErrors errors, DecimationOptions options,
                                             ProgressReporter* costing)
    : options_(std::move(options)), stop_{options_.maxError, options_.targetSamples}, mesh_(mesh),
      rules_(mesh_,
             options_.cost == CollapseCost::ServedSamples && !options_.fixedBoundary ? BoundaryRule::Shrinking
                                                                                     : BoundaryRule::Fixed,
             options_.frozen) {
  TRIWALK_CHECK(options_.cost == CollapseCost::Centroid ? errors.triangles != nullptr : errors.samples != nullptr,
                "the decimator needs the error source of its cost");
  TRIWALK_CHECK(options_.sampleWeights.empty() || options_.sampleWeights.size() == mesh.positions().size(),
                "one weight per sample");
  TRIWALK_CHECK(options_.frozen.empty() || options_.frozen.size() == mesh.positions().size(), "one frozen flag per sample");
  TRIWALK_CHECK(options_.counted.empty() || options_.counted.size() == mesh.positions().size(), "one counted flag per sample");
  for (int v : mesh.vertices()) countedCount_ += counts(v);
  if (options_.cost == CollapseCost::Centroid) {
    cost_ = std::make_unique<CentroidCost>(mesh_, *errors.triangles, options_.areaWeightedCost, statistics_);
  } else {
    auto served = std::make_unique<ServedSampleCost>(mesh, mesh_, *errors.samples, options_.sampleWeights,
                                                     options_.pricedSamples, statistics_, costing);
    servedCost_ = served.get();
    cost_ = std::move(served);
  }
  costEdges(mesh_.edges(), costing);
}

double EdgeCollapseDecimator::servedSampleMeanError() const { return servedCost_ ? servedCost_->meanError() : 0.0; }

bool EdgeCollapseDecimator::planFor(int a, int b, int placement, PlacementKind kind, CollapsePlan& plan,
                                 bool straightStretches) const {
  if (!rules_.planCollapse(a, b, placement, kind, plan, straightStretches)) return false;
  cost_->prepare(a, b, plan);
  return true;
}

// ------------------------------------------------------------- pricing --

// Costs a batch of edges: every candidate collapse is planned first, the
// errors they need are computed together (in parallel), then each edge
// takes its cheapest valid candidate (ties: candidate order).
void EdgeCollapseDecimator::costEdges(const std::vector<Edge>& edges, ProgressReporter* progress) {
  std::vector<EdgeState> states = priceEdges(edges, Resort::None, progress);
  for (size_t i = 0; i < edges.size(); ++i) commit(edges[i], std::move(states[i]));
}

void EdgeCollapseDecimator::commit(const Edge& edge, EdgeState state) {
  state.stamp = nextStamp_++;
  ++statistics_.edgesCosted;
  if (std::isfinite(state.cost)) heap_.push({state.cost, edge.first, edge.second, state.stamp});
  edges_[edge] = std::move(state);
}

std::vector<EdgeCollapseDecimator::EdgeState> EdgeCollapseDecimator::priceEdges(const std::vector<Edge>& edges,
                                                                                Resort resort,
                                                                                ProgressReporter* progress) {
  struct Candidate {
    size_t edge;
    CollapsePlan plan;
  };
  std::vector<Candidate> candidates;
  std::vector<EdgeState> states(edges.size());
  const int pieces = resort == Resort::Removals ? mesh_.piecesWithout({}) : 0;
  for (size_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = edges[i];
    const std::vector<PlacementCandidate> tries =
        resort == Resort::Removals
            ? std::vector<PlacementCandidate>{{b, PlacementKind::Removal}, {a, PlacementKind::Removal}}
            : placementCandidates(mesh_, a, b, options_.oneRingCandidates, states[i].nearest);
    for (const PlacementCandidate& placement : tries) {
      CollapsePlan candidate;
      if (placement.kind == PlacementKind::Removal) {
        const int leaving = placement.sample == a ? b : a;
        if (!rules_.planRemoval(leaving, placement.sample, pieces, candidate)) continue;
        cost_->prepare(leaving, placement.sample, candidate);
      } else if (!planFor(a, b, placement.sample, placement.kind, candidate, resort == Resort::StraightStretches)) {
        continue;
      }
      candidates.push_back({i, std::move(candidate)});
    }
  }
  std::vector<const CollapsePlan*> plans;
  for (const Candidate& candidate : candidates) plans.push_back(&candidate.plan);
  cost_->ensureErrors(plans, progress);
  for (Candidate& candidate : candidates) {
    EdgeState& state = states[candidate.edge];
    const auto [cost, error] = cost_->price(candidate.plan);
    if (stop_.refuses(error)) {
      state.lowestRefusedError = std::min(state.lowestRefusedError, error);
      continue;
    }
    if (cost < state.cost) {
      state.cost = cost;
      state.error = error;
      state.plan = std::move(candidate.plan);
    }
  }
  return states;
}

// ------------------------------------------------------------ collapse --

// The heap's top after dropping stale entries and re-checking the top's
// cost, or nullptr if no valid collapse is left.
const EdgeCollapseDecimator::HeapEntry* EdgeCollapseDecimator::peekValid() {
  while (!heap_.empty()) {
    const HeapEntry top = heap_.top();
    const auto state = edges_.find({top.first, top.second});
    if (state == edges_.end() || state->second.stamp != top.stamp) {
      heap_.pop();
      ++statistics_.staleEntriesSkipped;
      continue;
    }
    // A sample far away may have been freed or taken since this edge was
    // costed: cost it again; if anything changed, the new entry competes.
    const double oldCost = state->second.cost;
    const int oldPlacement = state->second.plan.placement;
    heap_.pop();
    costEdges({{top.first, top.second}});
    const EdgeState& fresh = edges_.at({top.first, top.second});
    if (fresh.cost == oldCost && fresh.plan.placement == oldPlacement) return &heap_.top();
    ++statistics_.collapseChecksFailed;
  }
  return lastResort();
}

// No collapse is valid, none refused by the threshold either: only now
// may a reference leave a straight stretch of the boundary (staysInside).
// On a lattice of samples every corridor's sides are such stretches, and
// without this a level whose corridors stand two references wide stops
// far above the count asked for (oacmpdm1: 133 of 469 samples for any
// target). Only as a last resort, because taking these whenever they are
// cheapest changed selections that never got stuck, for the worse on the
// built-in scene (docs/history/RESULTS-2026-11.md, "References off straight stretches of
// the boundary"). If none of those is valid (none refused either), a
// boundary reference may leave with all its triangles (CollapseRules::planRemoval):
// no collapse ever cuts a ring of triangles, so a loop of corridors
// otherwise stops where its ring is as thin as it can be (oacmpdm1 at 66
// samples). The rules depend on the mesh alone: every edge is priced with
// them and only the cheapest keeps that price (the others' refusals would
// count as ordinary ones and stop a later search); if it is asked for
// again, its entry fails the check at the top (an ordinary price) and
// this runs again on the same mesh.
const EdgeCollapseDecimator::HeapEntry* EdgeCollapseDecimator::lastResort() {
  if (!rules_.boundaryMayShrink() || std::isfinite(lowestRefusedError())) return nullptr;
  const std::vector<Edge> edges = liveEdges();
  if (const HeapEntry* stretch = commitCheapest(edges, priceEdges(edges, Resort::StraightStretches))) {
    ++statistics_.straightStretchSearches;
    return stretch;
  }
  if (std::isfinite(lowestRefusedError())) return nullptr;  // over the threshold: the stop reports it
  const HeapEntry* removal = commitCheapest(edges, priceEdges(edges, Resort::Removals));
  if (removal) ++statistics_.removals;
  return removal;
}

const EdgeCollapseDecimator::HeapEntry* EdgeCollapseDecimator::commitCheapest(const std::vector<Edge>& edges,
                                                                              std::vector<EdgeState> states) {
  size_t best = edges.size();
  for (size_t i = 0; i < edges.size(); ++i) {
    if (std::isfinite(states[i].cost) && (best == edges.size() || states[i].cost < states[best].cost)) best = i;
  }
  if (best == edges.size()) {
    for (size_t i = 0; i < edges.size(); ++i) commit(edges[i], std::move(states[i]));
    return nullptr;
  }
  commit(edges[best], std::move(states[best]));
  return &heap_.top();
}

std::vector<EdgeCollapseDecimator::Edge> EdgeCollapseDecimator::liveEdges() const {
  std::vector<Edge> edges;
  edges.reserve(edges_.size());
  for (const auto& [edge, state] : edges_) edges.push_back(edge);
  return edges;
}

std::optional<Collapse> EdgeCollapseDecimator::peekNextCollapse() {
  const HeapEntry* top = peekValid();
  if (!top) return std::nullopt;
  return logEntry({top->first, top->second}, edges_.at({top->first, top->second}));
}

Collapse EdgeCollapseDecimator::logEntry(const Edge& edge, const EdgeState& state) const {
  Collapse collapse;
  collapse.first = edge.first;
  collapse.second = edge.second;
  if (state.plan.kind == PlacementKind::Removal) {  // the reference that leaves first
    collapse.first = edge.first == state.plan.placement ? edge.second : edge.first;
    collapse.second = state.plan.placement;
  }
  collapse.placement = state.plan.placement;
  collapse.kind = state.plan.kind;
  collapse.cost = state.cost;
  collapse.error = state.error;
  for (int t : state.plan.removed) collapse.removed.push_back(canonicalTriangle(mesh_.triangle(t)));
  collapse.added = state.plan.added;
  std::sort(collapse.removed.begin(), collapse.removed.end());
  return collapse;
}

double EdgeCollapseDecimator::nextCost() {
  const HeapEntry* top = peekValid();
  return top ? top->cost : kInfinity;
}

bool EdgeCollapseDecimator::isValidCollapse(int first, int second, int placement) const {
  if (placement != first && placement != second && mesh_.isVertex(placement)) return false;
  CollapsePlan plan;
  return rules_.planCollapse(first, second, placement, PlacementKind::First, plan);
}

bool EdgeCollapseDecimator::isValidRemoval(int leaving, int staying) const {
  if (!mesh_.isVertex(leaving) || !mesh_.isVertex(staying)) return false;
  CollapsePlan plan;
  return rules_.planRemoval(leaving, staying, mesh_.piecesWithout({}), plan);
}

std::optional<Collapse> EdgeCollapseDecimator::evaluateCollapse(int first, int second, int placement) {
  if (placement != first && placement != second && mesh_.isVertex(placement)) return std::nullopt;
  CollapsePlan plan;
  const PlacementKind kind = placement == first ? PlacementKind::First : placement == second ? PlacementKind::Second
                                                                                              : PlacementKind::Midpoint;
  if (!planFor(first, second, placement, kind, plan)) return std::nullopt;
  cost_->ensureErrors({&plan});
  const auto [cost, error] = cost_->price(plan);
  if (stop_.refuses(error)) return std::nullopt;
  EdgeState state;
  state.cost = cost;
  state.error = error;
  state.plan = std::move(plan);
  return logEntry({first, second}, state);
}

void EdgeCollapseDecimator::apply(const Edge& edge, const EdgeState& state) {
  const auto [a, b] = edge;
  const CollapsePlan& plan = state.plan;
  log_.push_back(logEntry(edge, state));
  const int firstAdded = mesh_.apply(a, b, plan);
  const std::vector<int> gained = cost_->follow(plan, firstAdded);
  countedCount_ += counts(plan.placement) - counts(a) - counts(b);
  for (auto it = edges_.begin(); it != edges_.end();) {
    it = (it->first.first == a || it->first.second == a || it->first.first == b || it->first.second == b) ? edges_.erase(it)
                                                                                                         : std::next(it);
  }
  costEdges(affectedEdges(edge, plan, gained));
}

// The edges whose updated triangles changed (those touching the placement
// or a neighbour of it, and around the triangles the cost says gained
// samples), and those whose midpoint candidate changed: it was the
// placement, or a or b is now free and nearer. Re-costing lazily, only
// the placement's edges are priced now, and those without a finite cost:
// they have no heap entry that would bring them back when they became
// valid. The others are priced again when they reach the heap's top.
std::vector<CollapseMesh::Edge> EdgeCollapseDecimator::affectedEdges(const Edge& collapsed, const CollapsePlan& plan,
                                                                     const std::vector<int>& gained) const {
  const auto [a, b] = collapsed;
  const auto pricedNow = [&](const Edge& other, const EdgeState* known) {
    if (!options_.lazyRecosting || other.first == plan.placement || other.second == plan.placement) return true;
    return !known || !std::isfinite(known->cost);
  };
  std::set<Edge> affected;
  std::vector<int> around = mesh_.neighboursOf(plan.placement);
  around.push_back(plan.placement);
  if (plan.kind == PlacementKind::Removal) {  // the fan's outline, not all of it around the placement
    for (const Triangle& t : log_.back().removed) around.insert(around.end(), t.begin(), t.end());
  }
  for (int t : gained) around.insert(around.end(), mesh_.triangle(t).begin(), mesh_.triangle(t).end());
  for (int w : around) {
    for (int x : mesh_.neighboursOf(w)) {
      const Edge other{std::min(w, x), std::max(w, x)};
      const auto known = edges_.find(other);
      if (pricedNow(other, known == edges_.end() ? nullptr : &known->second)) affected.insert(other);
    }
  }
  for (const auto& [other, otherState] : edges_) {
    if (!pricedNow(other, &otherState)) continue;
    const glm::dvec2 midpoint = 0.5 * (mesh_.position(other.first) + mesh_.position(other.second));
    bool changed = otherState.nearest.sample == plan.placement;
    for (int freed : {a, b}) {
      changed |= freed != plan.placement && glm::length(mesh_.position(freed) - midpoint) < otherState.nearest.distance;
    }
    if (changed) affected.insert(other);
  }
  return {affected.begin(), affected.end()};
}

bool EdgeCollapseDecimator::step() {
  if (stop_.reached(countedCount_)) {
    stopReason_ = StopReason::TargetReached;
    return false;
  }
  const HeapEntry* top = peekValid();
  if (!top) {
    stopReason_ = std::isfinite(lowestRefusedError()) ? StopReason::MaxError : StopReason::NoValidCollapse;
    return false;
  }
  const Edge edge{top->first, top->second};
  heap_.pop();
  const EdgeState state = edges_.at(edge);
  apply(edge, state);
  stopReason_ = StopReason::None;
  return true;
}

StopReason EdgeCollapseDecimator::run(ProgressReporter* progress) {
  while (true) {
    if (interruptRequested()) {
      stopReason_ = StopReason::Interrupted;
      break;
    }
    if (!step()) break;
    if (progress) {
      char status[96];
      std::snprintf(status, sizeof status, "samples %d  cost %.3f", mesh_.vertexCount(), log_.back().cost);
      progress->setStatus(status);
      progress->setTotal(log_.size() + expectedRemainingCollapses());
      progress->advance();
    }
  }
  return stopReason_;
}

double EdgeCollapseDecimator::lowestRefusedError() const {
  double lowest = kInfinity;
  for (const auto& [edge, state] : edges_) lowest = std::min(lowest, state.lowestRefusedError);
  return lowest;
}

size_t EdgeCollapseDecimator::expectedRemainingCollapses() const {
  return stop_.remainingCollapses(countedCount_, log_);
}

}  // namespace triwalk
