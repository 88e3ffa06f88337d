#pragma once
// Edge-collapse decimation of a triangulated set of views: the paper's
// Sec. III-C with the definitions of DESIGN.md ("Triangle error and
// decimation"), shaped like meshoptimizer's simplifier (small steps over
// flat arrays) with libigl's lazy-deletion heap.
//
//   cost every edge (v1, v2): for each placement p among v1, v2 and the
//     free dense sample nearest the midpoint (optionally every free sample
//     inside the two one-rings) whose collapse (v1, v2) -> p is valid,
//     the mean error of the triangles around p afterwards (paper Fig. 4);
//     the edge's cost is the lowest, its placement that p
//   repeat:
//     pop the cheapest edge (skip entries whose stamp is stale), re-check
//     its cost (a far sample may have been freed or taken), stop if it
//     exceeds the threshold, collapse it, log it, and re-cost every edge
//     whose updated triangles changed: those touching p or a neighbour of p
//   until the error threshold, the target sample count, or no valid collapse.
//
// A collapse is valid only if the result is a manifold planar
// triangulation covering the same region:
//   - link condition: v1 and v2 share exactly the neighbours opposite their edge;
//   - two boundary vertices may only collapse along a boundary edge;
//   - every new triangle is counter-clockwise (exact predicate, never flat);
//   - the boundary never moves: a boundary vertex may be removed only where
//     it lies on the straight segment between its boundary neighbours, and p
//     must lie on that segment (hull corners stay).
// Triangle errors are cached by sorted vertex triple. Results do not
// depend on the thread count: only the error batches run in parallel.

#include "core/planar_geometry.h"
#include "core/triangle_error.h"
#include "core/view_mesh.h"

#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <unordered_map>
#include <vector>

namespace triwalk {

class ProgressReporter;

// Relocation is not a collapse: the refinement after decimation
// (core/selection_refinement.h) moved sample `first` to `placement`; the
// sample count stays and `second` is -1.
enum class PlacementKind { First, Second, Midpoint, OneRing, Relocation };
const char* placementName(PlacementKind kind);

// One logged collapse (or relocation): replaying removed -> added (forward)
// or added -> removed (backward) moves between consecutive meshes.
struct Collapse {
  int first = -1, second = -1;  // the edge (sample indices)
  int placement = -1;           // the sample that replaces them
  PlacementKind kind = PlacementKind::First;
  double cost = 0.0;
  std::vector<Triangle> removed;
  std::vector<Triangle> added;
};

enum class StopReason { None, MaxError, TargetReached, NoValidCollapse, Interrupted };
const char* stopReasonName(StopReason reason);

struct DecimationOptions {
  double maxError = 1.85;        // stop before a collapse costing more; <= 0: no threshold
  int targetSamples = 0;         // stop at this many samples; 0: no target
  bool oneRingCandidates = false;
  bool areaWeightedCost = true;  // false: the paper's plain mean over the updated triangles
};

struct DecimationStatistics {
  uint64_t errorsComputed = 0;   // triangle errors evaluated
  uint64_t cacheHits = 0;        // triangle errors served from the cache
  uint64_t staleEntriesSkipped = 0;
  uint64_t edgesCosted = 0;
  uint64_t collapseChecksFailed = 0;  // popped entries whose cost had changed
};

class EdgeCollapseDecimator {
public:
  // Costs every edge up front (the long part on a dense mesh): costing, if
  // given, counts the triangle errors it computes; Ctrl-C throws Interrupted.
  EdgeCollapseDecimator(const ViewMesh& mesh, TriangleErrorSource& errors, DecimationOptions options,
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
  // Whether collapsing the edge (first, second) into placement is valid now.
  bool isValidCollapse(int first, int second, int placement) const;
  StopReason stopReason() const { return stopReason_; }
  // For the time left: the collapses to the target count, or, under an
  // error threshold, until the cost reaches it at the pace of the last 32.
  size_t expectedRemainingCollapses() const;
  int vertexCount() const { return vertexCount_; }
  int triangleCount() const;
  ViewMesh mesh() const;
  const std::vector<Collapse>& log() const { return log_; }
  const DecimationStatistics& statistics() const { return statistics_; }
  // Error of a triangle, from the cache or computed.
  double triangleError(const Triangle& triangle);

private:
  struct Plan {
    int placement = -1;
    PlacementKind kind = PlacementKind::First;
    std::vector<int> removed;         // triangle ids
    std::vector<Triangle> added;
  };
  struct EdgeState {
    uint64_t stamp = 0;
    double cost = std::numeric_limits<double>::infinity();
    Plan plan;
    int midpointSample = -1;          // the free sample nearest the midpoint
    double midpointDistance = 0.0;
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

  std::vector<int> neighboursOf(int vertex) const;
  std::vector<int> edgeTriangles(int a, int b) const;
  std::vector<int> boundaryNeighbours(int vertex) const;
  bool onOpenSegment(int sample, int from, int to) const;
  bool simulate(int a, int b, int placement, PlacementKind kind, Plan& plan) const;
  std::vector<std::pair<int, PlacementKind>> candidates(int a, int b, EdgeState& state) const;
  void costEdges(const std::vector<Edge>& edges, ProgressReporter* progress = nullptr);
  void ensureErrors(const std::vector<Triangle>& triangles, ProgressReporter* progress = nullptr);
  double meanError(const std::vector<Triangle>& triangles);
  const HeapEntry* peekValid();
  void apply(const Edge& edge, const EdgeState& state);

  std::vector<glm::dvec2> positions_;
  std::vector<Triangle> triangles_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> incident_;  // alive triangles of each sample
  std::vector<char> isVertex_;
  int vertexCount_ = 0;
  TriangleErrorSource& errors_;
  DecimationOptions options_;
  std::unordered_map<uint64_t, double> cache_;
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
