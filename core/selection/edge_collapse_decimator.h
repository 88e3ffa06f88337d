#pragma once
// Edge-collapse decimation of a triangulated set of views: the paper's
// Sec. III-C with the definitions of docs/DESIGN.md ("Selection"). A
// small engine (this file: libigl's lazy-deletion heap over the edges)
// runs units that each decide one thing, in core/selection/collapse/:
//
//   CollapseMesh         the triangles over flat arrays (collapse_mesh.h)
//   placementCandidates  where the merged reference may go (placement_candidates.h)
//   CollapseRules        which collapses are valid; the boundary rule (collapse_rules.h)
//   CostModel            what a collapse costs: CentroidCost or ServedSampleCost
//   StopRule             a target count or an error threshold (stop_rule.h)
//
// The paper's set (--preset paper): CentroidCost (unweighted), the three
// placements (either end, the free sample nearest the midpoint),
// BoundaryRule::Fixed, eager re-costing, StopRule at the error 1.85.
// triwalk's default: ServedSampleCost (priced from 32 samples), the same
// placements, BoundaryRule::Shrinking with its two last resorts, lazy
// re-costing, StopRule at 1.36 x the dense triangulation's mean error.
//
//   price every edge: for each valid placement, its cost; the edge keeps
//     the cheapest (ties: candidate order)
//   repeat:
//     pop the cheapest edge (skip entries whose stamp is stale), price it
//     again (a far sample may have been freed or taken), collapse it, log
//     it, and price again the edges whose updated triangles changed: those
//     touching the placement or a neighbour of it (lazily: only the
//     placement's edges; the others keep their cost until they reach the
//     top and are priced again there)
//   until the stop rule holds or no valid collapse is left.
//
// Results do not depend on the thread count: only the error batches run
// in parallel, and every sum runs in a canonical order.

#include "core/geometry/view_mesh.h"
#include "core/selection/collapse/collapse_log.h"
#include "core/selection/collapse/collapse_mesh.h"
#include "core/selection/collapse/collapse_rules.h"
#include "core/selection/collapse/cost_model.h"
#include "core/selection/collapse/decimation_statistics.h"
#include "core/selection/collapse/placement_candidates.h"
#include "core/selection/collapse/stop_rule.h"
#include "core/selection/triangle_error.h"

#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <queue>
#include <string>
#include <vector>

namespace triwalk {

class ProgressReporter;
class ServedSampleCost;

enum class StopReason { None, MaxError, TargetReached, NoValidCollapse, Interrupted };
const char* stopReasonName(StopReason reason);

enum class CollapseCost { ServedSamples, Centroid };
const char* collapseCostName(CollapseCost cost);
// Parses "served-samples" or "centroid"; throws InputError.
CollapseCost parseCollapseCost(const std::string& name);
// DecimationOptions::lazyRecosting by name: "lazy" or "eager".
const char* recostingName(bool lazyRecosting);
// Parses "lazy" or "eager" (true for lazy); throws InputError.
bool parseLazyRecosting(const std::string& name);

// The paper's absolute error threshold (its Table 1), on its error scale.
inline constexpr double kPaperMaxError = 1.85;

struct DecimationOptions {
  double maxError = kPaperMaxError;  // no collapse whose error exceeds this; <= 0: no threshold
  int targetSamples = 0;         // stop at this many samples; 0: no target
  bool oneRingCandidates = false;
  CollapseCost cost = CollapseCost::ServedSamples;
  // Served-sample cost: keep the paper's fixed boundary instead of letting
  // it shrink (the centroid cost always keeps it: it cannot price what
  // leaves the mesh).
  bool fixedBoundary = false;
  bool areaWeightedCost = true;  // centroid cost: false for the paper's plain mean over the updated triangles
  // Served-sample cost: each sample's share of the walkthrough area
  // (sampleAreaWeights), so that sums over samples estimate the area's
  // error; empty: equal shares.
  std::vector<double> sampleWeights;
  // Served-sample cost: price a collapse from at most this many of the
  // samples it serves, besides the vertices it frees (which are always
  // priced); 0: all of them (collapse/served_sample_cost.h).
  int pricedSamples = 32;
  // After a collapse, cost only the placement's edges at once; the other
  // edges it changed keep their cost in the heap until they reach its top,
  // where every edge is costed again before it collapses.
  bool lazyRecosting = true;
  // By sample index (empty: none): a frozen reference is never removed and
  // a frozen free sample never becomes a reference. A tiled selection's
  // seam pass freezes everything but the band along a tile's border.
  std::vector<char> frozen = {};
  // By sample index (empty: every sample): only these count toward
  // targetSamples. A tile counts its core's references, the ones it keeps:
  // counted over the whole tile, the references its margin held (dropped
  // when the tiles are stitched) left the cores short of the target.
  std::vector<char> counted = {};
};

// Where the costs come from: triangle errors for the centroid cost,
// reconstruction errors of dense samples for the served-sample cost.
struct DecimationErrors {
  TriangleErrorSource* triangles = nullptr;
  ReconstructionErrorSource* samples = nullptr;
};

class EdgeCollapseDecimator {
public:
  // Costs every edge up front (the long part on a dense mesh): costing, if
  // given, counts the errors it computes; Ctrl-C throws Interrupted. The
  // cost's error source must be given.
  EdgeCollapseDecimator(const ViewMesh& mesh, DecimationErrors errors, DecimationOptions options,
                        ProgressReporter* costing = nullptr);

  // Performs the cheapest valid collapse unless a stop condition holds;
  // returns false and sets stopReason() when it stops.
  bool step();
  // Collapses until a stop condition; reports progress; Ctrl-C stops it.
  StopReason run(ProgressReporter* progress = nullptr);

  // The cheapest valid collapse (what step() would do, stop conditions
  // aside), or nothing if none is left.
  std::optional<Collapse> peekNextCollapse();
  // Its cost, +inf if there is none.
  double nextCost();
  // After stopping at the threshold: the lowest error of a collapse it
  // refused (+inf if none was refused).
  double lowestRefusedError() const;
  // Whether collapsing the edge (first, second) into placement is valid now,
  // leaving aside the last resorts (a reference off a straight stretch of
  // the boundary, or removed with its triangles, valid only where nothing
  // else is: see lastResort).
  bool isValidCollapse(int first, int second, int placement) const;
  // Whether reference `leaving` may leave with all its triangles now,
  // keeping its boundary neighbour `staying` (PlacementKind::Removal; made
  // only as the last of the last resorts).
  bool isValidRemoval(int leaving, int staying) const;
  // That collapse with its cost and error as the decimator would rank it
  // (not performed), or nothing if it is invalid or over the threshold.
  std::optional<Collapse> evaluateCollapse(int first, int second, int placement);
  StopReason stopReason() const { return stopReason_; }
  // For the time left: the collapses to the target count, or, under an
  // error threshold, until the error reaches it at the pace of the last 32.
  size_t expectedRemainingCollapses() const;
  int vertexCount() const { return mesh_.vertexCount(); }
  int triangleCount() const { return mesh_.triangleCount(); }
  ViewMesh mesh() const { return mesh_.viewMesh(); }
  const std::vector<Collapse>& log() const { return log_; }
  const DecimationStatistics& statistics() const { return statistics_; }
  // Served-sample cost: the weighted mean error of the dense samples that
  // are not references, each from the triangle serving it.
  double servedSampleMeanError() const;

private:
  using Edge = CollapseMesh::Edge;
  struct EdgeState {
    uint64_t stamp = 0;
    double cost = std::numeric_limits<double>::infinity();
    double error = 0.0;
    double lowestRefusedError = std::numeric_limits<double>::infinity();  // over the threshold
    CollapsePlan plan;
    // Of its placements, the free sample nearest the midpoint (distance 0
    // where no placement was tried, as for a removal: nothing is nearer).
    NearestToMidpoint nearest{-1, 0.0};
  };
  struct HeapEntry {
    double cost;
    int first, second;
    uint64_t stamp;
    bool operator>(const HeapEntry& other) const {
      if (cost != other.cost) return cost > other.cost;
      if (first != other.first) return first > other.first;
      return second > other.second;
    }
  };
  // What a pricing may try besides the ordinary collapses: nothing, a
  // reference off a straight stretch of the boundary, or only removals.
  enum class Resort { None, StraightStretches, Removals };

  // 1 for a sample that counts toward the target (DecimationOptions::counted).
  int counts(int sample) const { return options_.counted.empty() || options_.counted[size_t(sample)] ? 1 : 0; }
  // The collapse of edge (a, b) into placement, planned and prepared for
  // pricing, if valid.
  bool planFor(int a, int b, int placement, PlacementKind kind, CollapsePlan& plan, bool straightStretches = false) const;
  // Prices every candidate of each edge and commits each edge's state.
  void costEdges(const std::vector<Edge>& edges, ProgressReporter* progress = nullptr);
  // Each edge's state (its cheapest valid candidate), not committed.
  std::vector<EdgeState> priceEdges(const std::vector<Edge>& edges, Resort resort,
                                    ProgressReporter* progress = nullptr);
  // Of priced states, the cheapest valid one committed (returned), or, if
  // none is valid, all committed (their refusals count) and none returned.
  const HeapEntry* commitCheapest(const std::vector<Edge>& edges, std::vector<EdgeState> states);
  // Makes state the edge's own, with a heap entry if it has a cost.
  void commit(const Edge& edge, EdgeState state);
  const HeapEntry* peekValid();
  const HeapEntry* lastResort();
  std::vector<Edge> liveEdges() const;
  // The log's entry for making an edge's state.
  Collapse logEntry(const Edge& edge, const EdgeState& state) const;
  void apply(const Edge& edge, const EdgeState& state);
  // The edges to price again after a collapse (see apply).
  std::vector<Edge> affectedEdges(const Edge& collapsed, const CollapsePlan& plan, const std::vector<int>& gained) const;

  DecimationOptions options_;
  StopRule stop_;
  CollapseMesh mesh_;
  CollapseRules rules_;
  DecimationStatistics statistics_;
  std::unique_ptr<CostModel> cost_;
  ServedSampleCost* servedCost_ = nullptr;  // cost_, under the served-sample cost
  int countedCount_ = 0;  // vertices that count toward the target (DecimationOptions::counted)
  std::map<Edge, EdgeState> edges_;
  std::priority_queue<HeapEntry, std::vector<HeapEntry>, std::greater<HeapEntry>> heap_;
  uint64_t nextStamp_ = 1;
  std::vector<Collapse> log_;
  StopReason stopReason_ = StopReason::None;
};

}  // namespace triwalk
