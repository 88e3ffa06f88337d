#pragma once
// The selections edge collapse is compared with, at the same sample count:
//   uniform:  a regular sub-grid of the capture paths (the paper's (b)),
//   k-medoids: position-only clustering, as MPEG's immersive-video test
//             model picks basic views,
//   random:   a seeded random subset.
// Each returns sorted sample indices; triangulate them with
// ViewMesh::delaunay.

#include "core/io/dataset.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace triwalk {

// Needs each sample's path and step; a sub-grid of paths and steps near
// count samples with even spacing (it may hold a few more or fewer),
// corners included. Throws InputError if the manifest lacks paths.
std::vector<int> uniformSelection(const Dataset& dataset, int count);

// Deterministic: greedy farthest-point start, then Voronoi iteration
// (assign to nearest medoid, move each medoid to its cluster's best
// member) until nothing changes.
std::vector<int> kMedoidsSelection(std::span<const glm::dvec2> positions, int count);

std::vector<int> randomSelection(int sampleCount, int count, unsigned seed);

}  // namespace triwalk
