#pragma once
// The selections edge collapse is compared with, by name, at any count:
// eval's rows and its --counts table and the suite's columns are built
// here, the walking distances once per data set. Greedy insertion, which
// needs the data set's errors, is in reference_selection.h.

#include "core/geometry/view_mesh.h"
#include "core/io/dataset.h"
#include "core/selection/walking_distances.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace triwalk {

// The geometric baselines, in the order tables show them: uniform,
// uniform_region, kmedoids, geodesic_kmedoids, farthest_point, random.
const std::vector<std::string>& geometricBaselines();

// How tables name a method: the baselines, "initial", "edge_collapse",
// "greedy_insertion" and "insertion_refined".
const char* methodLabel(const std::string& method);

class BaselineSet {
public:
  // seed: the random baseline's.
  BaselineSet(const Dataset& dataset, unsigned seed);

  // The baseline's samples at count views (sorted).
  std::vector<int> samples(const std::string& method, int count) const;
  // Their triangulation in the walkable region; throws InputError naming
  // the baseline when there is none (samples collinear, say).
  ViewMesh mesh(const std::string& method, int count) const;

private:
  const Dataset& dataset_;
  std::vector<glm::dvec2> positions_;
  WalkableRegion region_;
  WalkingDistances walking_;
  unsigned seed_;
};

}  // namespace triwalk
