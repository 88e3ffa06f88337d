#pragma once
// Edge-collapse decimation of a triangulated set of views: the paper's
// Sec. III-C with the definitions of docs/DESIGN.md ("Selection"), shaped
// like meshoptimizer's simplifier (small steps over flat arrays) with
// libigl's lazy-deletion heap.
//
//   cost every edge (v1, v2): for each placement p among v1, v2 and the
//     free dense sample nearest the midpoint (optionally every free sample
//     inside the two one-rings) whose collapse (v1, v2) -> p is valid,
//     the cost of the mesh after it; the edge's cost is the lowest, its
//     placement that p
//   repeat:
//     pop the cheapest edge (skip entries whose stamp is stale), re-check
//     its cost (a far sample may have been freed or taken), collapse it,
//     log it, and re-cost every edge whose updated triangles changed:
//     those touching p or a neighbour of p (lazily: only p's edges; the
//     others keep their cost until they reach the top and are re-checked)
//   until the target sample count, or no valid collapse is left under
//   the error threshold.
//
// Two costs (CollapseCost):
//   served samples (default): every dense sample that is not a reference
//     is served by the triangle around it, as a walker standing there
//     would be; a collapse costs the increase of the total reconstruction
//     error over the samples its new triangles serve (those freed by it
//     included). Greedy on this cost removes, at each step, the reference
//     whose loss the walkthrough feels least, measured where it is felt.
//     The threshold applies to the mean error of those samples. Past
//     pricedSamples, a stratified random subset of them prices it.
//   centroid (the paper's): the mean error of the updated triangles, each
//     measured at one destination near its centroid, weighted by area
//     unless asked otherwise; the threshold applies to that mean.
//
// A collapse is valid only if the result is a manifold planar
// triangulation covering the same region (or, where the boundary may
// shrink, a part of it):
//   - link condition: v1 and v2 share exactly the neighbours opposite their edge;
//   - two boundary vertices may only collapse along a boundary edge;
//   - every new triangle is counter-clockwise (exact predicate, never flat);
//   - fixed boundary (the centroid cost, or asked for): the boundary never
//     moves: a boundary vertex may be removed only where it lies on the
//     straight segment between its boundary neighbours, and p must lie on
//     that segment (hull corners stay);
//   - shrinking boundary (the served-sample cost): the new triangles lie
//     inside the removed ones; a reference may leave a straight stretch
//     of the boundary only once no other collapse is valid, and a
//     boundary reference may leave with all its triangles (cutting a ring
//     of them open) only once no such collapse is valid either.
// Errors are cached (triangles by sorted vertex triple, served samples by
// triangle and sample). Results do not depend on the thread count: only
// the error batches run in parallel.

#include "core/geometry/planar_geometry.h"
#include "core/geometry/view_mesh.h"
#include "core/selection/sample_pricing.h"
#include "core/selection/triangle_error.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <set>
#include <span>
#include <unordered_map>
#include <vector>

namespace triwalk {

class ProgressReporter;

// Relocation is not a collapse: the refinement after decimation
// (core/selection/selection_refinement.h) moved sample `first` to `placement`; the
// sample count stays and `second` is -1. Removal: reference `first` left
// the mesh with all its triangles and none was added (a loop of corridors
// cut, see lastResort); `second` and `placement` are its neighbour along
// the boundary edge that stays a reference.
enum class PlacementKind { First, Second, Midpoint, OneRing, Relocation, Removal };
const char* placementName(PlacementKind kind);

// One logged collapse (or relocation): replaying removed -> added (forward)
// or added -> removed (backward) moves between consecutive meshes.
struct Collapse {
  int first = -1, second = -1;  // the edge (sample indices)
  int placement = -1;           // the sample that replaces them
  PlacementKind kind = PlacementKind::First;
  double cost = 0.0;   // what ranked it (see CollapseCost)
  double error = 0.0;  // what the threshold is compared with (see CollapseCost)
  std::vector<Triangle> removed;
  std::vector<Triangle> added;
};

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
  // priced); 0: all of them. See choosePricedSamples.
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

struct DecimationStatistics {
  uint64_t errorsComputed = 0;   // triangle (or served-sample) errors evaluated
  uint64_t cacheHits = 0;        // errors served from the cache
  uint64_t staleEntriesSkipped = 0;
  uint64_t edgesCosted = 0;
  uint64_t collapseChecksFailed = 0;  // popped entries whose cost had changed
  // Last-resort searches that found a collapse taking a reference off a
  // straight stretch of the boundary (see lastResort); in a run of step()
  // each is one such collapse.
  uint64_t straightStretchSearches = 0;
  // Last-resort searches, after those, that found a reference to remove
  // with all its triangles (PlacementKind::Removal).
  uint64_t removals = 0;
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
  int vertexCount() const { return vertexCount_; }
  int triangleCount() const;
  ViewMesh mesh() const;
  const std::vector<Collapse>& log() const { return log_; }
  const DecimationStatistics& statistics() const { return statistics_; }
  // Error of a triangle, from the cache or computed (centroid cost).
  double triangleError(const Triangle& triangle);
  // Served-sample cost: the weighted mean error of the dense samples that
  // are not references, each from the triangle serving it.
  double servedSampleMeanError() const;

private:
  struct Plan {
    int placement = -1;
    PlacementKind kind = PlacementKind::First;
    std::vector<int> removed;         // triangle ids
    std::vector<Triangle> added;
    std::vector<int> served;          // served-sample cost: the samples whose triangle changes
    std::vector<int> servedBy;        // per served sample: index into added, or -1 - id of an existing triangle
    std::vector<ServingRank> servedRank;  // of that triangle for the sample ({false, 0} inside)
    // Of served, those whose errors price the collapse (index into served, sorted), each
    // with the served weight it stands for over its own.
    std::vector<PricedSample> priced;
  };
  struct EdgeState {
    uint64_t stamp = 0;
    double cost = std::numeric_limits<double>::infinity();
    double error = 0.0;
    double lowestRefusedError = std::numeric_limits<double>::infinity();  // over the threshold
    Plan plan;
    int midpointSample = -1;          // the free sample nearest the midpoint
    double midpointDistance = 0.0;
  };
  struct SampleKey {
    uint64_t triangle;  // tripleKey of the sorted triangle
    int sample;
    bool operator==(const SampleKey&) const = default;
  };
  struct SampleKeyHash {
    size_t operator()(const SampleKey& key) const { return std::hash<uint64_t>()(key.triangle * 1000003u + uint64_t(key.sample)); }
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
  using Edge = std::pair<int, int>;

  bool isFrozen(int sample) const { return !options_.frozen.empty() && options_.frozen[size_t(sample)]; }
  // 1 for a sample that counts toward targetSamples (DecimationOptions::counted).
  int counts(int sample) const { return options_.counted.empty() || options_.counted[size_t(sample)] ? 1 : 0; }
  std::vector<int> neighboursOf(int vertex) const;
  std::vector<int> edgeTriangles(int a, int b) const;
  std::vector<int> boundaryNeighbours(int vertex) const;
  bool onOpenSegment(int sample, int from, int to) const;
  // straightStretches: see staysInside.
  bool simulate(int a, int b, int placement, PlacementKind kind, Plan& plan, bool straightStretches = false) const;
  // The removal of boundary reference `leaving` with its triangles, keeping
  // its boundary neighbour `staying` (the plan's placement); `pieces` is
  // piecesWithout({}), taken once for all the candidates on one mesh.
  bool simulateRemoval(int leaving, int staying, int pieces, Plan& plan) const;
  // Edge-connected pieces of the mesh without the given triangles (ids, sorted).
  int piecesWithout(const std::vector<int>& removed) const;
  bool boundaryMayShrink() const;
  bool keepsFixedBoundary(int a, int b, int placement, const std::vector<int>& boundaryA,
                          const std::vector<int>& boundaryB) const;
  bool staysInside(int a, int b, const Plan& plan, bool straightStretches) const;
  bool keepsEveryVertex(int a, int b, const Plan& plan) const;
  const Triangle& servingTriangle(const Plan& plan, size_t i) const;
  ServingRank servingRank(const Triangle& triangle, int sample) const;
  bool seesEachOther(int a, int b) const;
  double weightOf(int sample) const;
  std::vector<std::pair<int, PlacementKind>> candidates(int a, int b, EdgeState& state) const;
  void assignServedSamples(int a, int b, Plan& plan) const;
  void choosePricedSamples(int a, int b, Plan& plan) const;
  // The reconstruction giving the error of plan.served[i]; those of the
  // plan's priced samples, or of all its served ones.
  SampleReconstruction servedRequest(const Plan& plan, size_t i) const;
  std::vector<SampleReconstruction> pricedRequests(const Plan& plan) const;
  std::vector<SampleReconstruction> servedRequests(const Plan& plan) const;
  // Prices every candidate of each edge and commits each edge's state.
  void costEdges(const std::vector<Edge>& edges, ProgressReporter* progress = nullptr);
  // What a pricing may try besides the ordinary collapses: nothing, a
  // reference off a straight stretch of the boundary, or only removals.
  enum class Resort { None, StraightStretches, Removals };
  // Each edge's state (its cheapest valid candidate), not committed.
  std::vector<EdgeState> priceEdges(const std::vector<Edge>& edges, Resort resort,
                                    ProgressReporter* progress = nullptr);
  // Of priced states, the cheapest valid one committed (returned), or, if
  // none is valid, all committed (their refusals count) and none returned.
  const HeapEntry* commitCheapest(const std::vector<Edge>& edges, std::vector<EdgeState> states);
  // Makes state the edge's own, with a heap entry if it has a cost.
  void commit(const Edge& edge, EdgeState state);
  void ensureErrors(const std::vector<Triangle>& triangles, ProgressReporter* progress = nullptr);
  void ensureSampleErrors(const std::vector<SampleReconstruction>& requests, ProgressReporter* progress = nullptr);
  double sampleError(const Triangle& triangle, int sample) const;
  double meanError(const std::vector<Triangle>& triangles);
  // (cost, error) of a simulated collapse.
  std::pair<double, double> evaluate(const Plan& plan);
  void serveInitialSamples(const ViewMesh& mesh, ProgressReporter* progress);
  const HeapEntry* peekValid();
  const HeapEntry* lastResort();
  std::vector<Edge> liveEdges() const;
  // The log's entry for making an edge's state.
  Collapse logEntry(const Edge& edge, const EdgeState& state) const;
  void apply(const Edge& edge, const EdgeState& state);

  std::vector<glm::dvec2> positions_;
  std::vector<Triangle> triangles_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> incident_;  // alive triangles of each sample
  std::vector<char> isVertex_;
  int vertexCount_ = 0;
  int countedCount_ = 0;  // vertices that count toward targetSamples (DecimationOptions::counted)
  DecimationErrors errors_;
  DecimationOptions options_;
  std::unordered_map<uint64_t, double> cache_;  // triangle errors by tripleKey
  // Served-sample cost: the triangle serving each sample (-1 for
  // references), its error from there, and each triangle's samples.
  std::vector<int> home_;
  std::vector<double> homeError_;
  std::vector<ServingRank> homeRank_;  // {false, 0} inside the home triangle
  std::set<int> outside_;              // samples outside the mesh (where its boundary shrank)
  // The walkable region, and which samples see each other in it (filled
  // as asked: -1 unknown, 0 no, 1 yes; empty for a convex region).
  std::shared_ptr<const WalkableRegion> region_;
  mutable std::vector<int8_t> sight_;
  std::vector<std::vector<int>> served_;
  std::unordered_map<SampleKey, double, SampleKeyHash> sampleCache_;
  std::map<Edge, EdgeState> edges_;
  std::priority_queue<HeapEntry, std::vector<HeapEntry>, std::greater<HeapEntry>> heap_;
  uint64_t nextStamp_ = 1;
  std::vector<Collapse> log_;
  StopReason stopReason_ = StopReason::None;
  DecimationStatistics statistics_;
};

// The triangles after replaying the first `steps` collapses of a log onto
// the initial triangles (forward), or the initial triangles back from the
// final ones (steps counted from the end, backward).
std::vector<Triangle> replayForward(std::vector<Triangle> initial, std::span<const Collapse> log, size_t steps);
std::vector<Triangle> replayBackward(std::vector<Triangle> final, std::span<const Collapse> log, size_t steps);

// Samples left after the first `steps` entries of a log (relocations keep
// the count).
int samplesAfter(int initialSamples, std::span<const Collapse> log, size_t steps);
// The last step of the log at which `samples` samples are left (so the
// refinement is included at the final count), or nothing if the log never
// has that many.
std::optional<size_t> lastStepWithSamples(int initialSamples, std::span<const Collapse> log, int samples);

}  // namespace triwalk
