#pragma once
// The selections edge collapse is compared with, at the same sample count:
//   uniform:  a regular sub-grid of the capture paths (the paper's (b)),
//             a coarser sub-lattice of a region's capture lattice, or,
//             for samples without lattice coordinates (imported or
//             irregular captures), a regular lattice over their bounding
//             box, each node snapped to its nearest sample,
//   k-medoids: position-only clustering, as MPEG's immersive-video test
//             model picks basic views,
//   random:   a seeded random subset.
// walking_distances.h adds k-medoids and farthest-point sampling by
// walking distance inside the walkable region.
// Each returns sorted sample indices; triangulate them with
// ViewMesh::delaunay.

#include "core/io/dataset.h"

#include <glm/glm.hpp>

#include <functional>
#include <span>
#include <vector>

namespace triwalk {

// With each sample's path and step on a complete grid: a sub-grid of paths
// and steps near count samples with even spacing (it may hold a few more
// or fewer), corners included. With distinct paths and steps that do not
// fill their grid (a lattice clipped to a region): every sx-th column and
// sy-th row from an offset, the strides and offset whose count comes
// nearest count with the most even spacing, of those whose triangulation
// keeps a triangle inside the region. Otherwise latticeSelection.
std::vector<int> uniformSelection(const Dataset& dataset, int count);

// A regular lattice of square cells over the positions' bounding box,
// corners on the box's corners, each node snapped to the nearest position
// (ties: the lower index), repeats dropped; of the lattices from 2 x 2 up,
// the one whose distinct samples come nearest count (ties: the coarser).
std::vector<int> latticeSelection(std::span<const glm::dvec2> positions, int count);

// Deterministic: greedy farthest-point start, then Voronoi iteration
// (assign to nearest medoid, move each medoid to its cluster's best
// member) until nothing changes.
std::vector<int> kMedoidsSelection(std::span<const glm::dvec2> positions, int count);

// The Voronoi iteration of k-medoids from starting medoids among n
// samples, by any distance (straight or walking): assign each sample to
// its nearest medoid, move each medoid to its cluster's member of least
// summed distance, until nothing changes (at most 100 rounds). Sorted.
std::vector<int> refineMedoids(int n, std::vector<int> medoids, const std::function<double(int, int)>& distance);

std::vector<int> randomSelection(int sampleCount, int count, unsigned seed);

}  // namespace triwalk
