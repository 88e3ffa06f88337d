#include "core/selection/baseline_set.h"

#include "core/selection/baselines.h"
#include "core/selection/selection.h"
#include "core/support/errors.h"

#include <algorithm>

namespace triwalk {

const std::vector<std::string>& geometricBaselines() {
  static const std::vector<std::string> methods = {"uniform",           "uniform_region", "kmedoids",
                                                   "geodesic_kmedoids", "farthest_point", "random"};
  return methods;
}

const char* methodLabel(const std::string& method) {
  if (method == "initial") return "initial (a)";
  if (method == "uniform") return "uniform (b)";
  if (method == "uniform_region") return "uniform, region-aware";
  if (method == "edge_collapse") return "edge collapse (c)";
  if (method == "kmedoids") return "k-medoids";
  if (method == "geodesic_kmedoids") return "k-medoids, walking";
  if (method == "farthest_point") return "farthest point, walking";
  if (method == "random") return "random";
  if (method == "greedy_insertion") return "greedy insertion";
  if (method == "insertion_refined") return "greedy insertion, refined";
  return method.c_str();
}

BaselineSet::BaselineSet(const Dataset& dataset, unsigned seed)
    : dataset_(dataset),
      positions_(samplePositions(dataset)),
      region_(dataset.walkableRegion()),
      walking_(positions_, region_),
      seed_(seed) {}

std::vector<int> BaselineSet::samples(const std::string& method, int count) const {
  if (method == "uniform") return uniformSelection(dataset_, count);
  if (method == "uniform_region") {
    return regionUniformSelection(uniformSelection(dataset_, count), walking_, positions_, region_, count);
  }
  if (method == "kmedoids") return kMedoidsSelection(positions_, count);
  if (method == "geodesic_kmedoids") return geodesicKMedoidsSelection(walking_, count);
  if (method == "farthest_point") return farthestPointSelection(walking_, count);
  if (method == "random") return randomSelection(dataset_.sampleCount(), count, seed_);
  TRIWALK_CHECK(false, "an unknown baseline");
  return {};
}

ViewMesh BaselineSet::mesh(const std::string& method, int count) const {
  return ViewMesh::delaunay(positions_, samples(method, count), std::string(methodLabel(method)) + " baseline", &region_);
}

}  // namespace triwalk
