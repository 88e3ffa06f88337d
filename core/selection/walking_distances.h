#pragma once
// How far a walker goes from sample to sample inside the walkable region:
// shortest paths over the graph whose edges join samples within a few
// sample spacings whose straight segment stays in the region. Baselines
// that measure by it know the walls (issue 72): a medoid does not serve a
// room it cannot reach, however near it is in a straight line.

#include "core/geometry/walkable_region.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace triwalk {

class WalkingDistances {
public:
  // n x n distances in float (4 n^2 bytes: 0.8 MB for 450 samples, 16 MB
  // for 2,000); +infinity between parts of the region no path joins.
  WalkingDistances(std::span<const glm::dvec2> positions, const WalkableRegion& region);

  int count() const { return count_; }
  float operator()(int from, int to) const { return distances_[size_t(from) * size_t(count_) + size_t(to)]; }
  // The sample whose sum of walking distances to the others (within its
  // part of the region) is least, the lower index on a tie.
  int mostCentral() const;

private:
  int count_ = 0;
  std::vector<float> distances_;
};

// k-medoids by walking distance: the most central sample, then
// farthest-point picks, then Voronoi iteration (assign each sample to its
// nearest medoid, move each medoid to its cluster's best member) until
// nothing changes; kMedoidsSelection's steps with walking distances.
std::vector<int> geodesicKMedoidsSelection(const WalkingDistances& distances, int count);

// Farthest-point sampling by walking distance from the most central
// sample: each pick is the sample farthest from its nearest pick so far
// (the lower index on a tie). Sorted indices.
std::vector<int> farthestPointSelection(const WalkingDistances& distances, int count);

// The region-aware uniform baseline: a uniform lattice (uniformSelection)
// made exactly count views of triangles inside the region, so that its
// count is the number of views that serve. By walking distance: while it
// has fewer, the sample farthest from its nearest chosen one joins, what
// the lattice left furthest from every view (a room or corridor between
// its nodes or beyond their reach); while it has more, the chosen sample
// nearest another leaves, the lattice's most redundant node (ties: the
// lower index joins, the higher leaves). Then, while the triangulation in
// the region (ViewMesh::delaunay) keeps no triangle of some chosen sample
// (a lone node in a room or corridor, with no neighbour it sees across
// open floor), the samples nearest it by walking join one at a time until
// it has one (at most three), and those stay while the count is made up
// by the most redundant nodes leaving; a node that cannot be given one
// leaves for good and the count is made up again. So every room the
// lattice reached gets the fewest extra views that give it a triangle.
// Fewer than count only if the region has no more samples that can serve.
// Sorted indices; count >= 3.
std::vector<int> regionUniformSelection(std::vector<int> lattice, const WalkingDistances& distances,
                                        std::span<const glm::dvec2> positions, const WalkableRegion& region, int count);

// The same picks in the order they were made, with each one's walking
// distance to its nearest earlier pick (infinity for the first).
std::vector<std::pair<int, float>> farthestPointOrder(const WalkingDistances& distances, int count);

}  // namespace triwalk
