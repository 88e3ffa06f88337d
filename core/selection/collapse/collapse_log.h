#pragma once
// What a decimation records: each collapse (or the refinement's
// relocation) with the triangles it removed and added, so that the meshes
// between the dense triangulation and the selection can be replayed in
// either direction (the viewer's stepping, the selection file's log).

#include "core/geometry/planar_geometry.h"

#include <optional>
#include <span>
#include <vector>

namespace triwalk {

// Relocation is not a collapse: the refinement after decimation
// (core/selection/selection_refinement.h) moved sample `first` to
// `placement`; the sample count stays and `second` is -1. Removal:
// reference `first` left the mesh with all its triangles and none was
// added (a loop of corridors cut, see the decimator's last resorts);
// `second` and `placement` are its neighbour along the boundary edge that
// stays a reference.
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
