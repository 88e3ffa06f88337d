#pragma once
// The paper's cost (Sec. III-C, Fig. 4): a collapse costs the mean error
// of its updated triangles, each measured at one destination near its
// centroid, weighted by area unless asked otherwise (a triangle serves
// the part of the walkthrough space it covers); the threshold applies to
// that mean. It cannot price what leaves the mesh, so the boundary stays.

#include "core/selection/collapse/collapse_mesh.h"
#include "core/selection/collapse/cost_model.h"
#include "core/selection/collapse/decimation_statistics.h"
#include "core/selection/triangle_error.h"

#include <unordered_map>

namespace triwalk {

class CentroidCost : public CostModel {
public:
  CentroidCost(const CollapseMesh& mesh, TriangleErrorSource& errors, bool areaWeighted,
               DecimationStatistics& statistics);

  void prepare(int, int, CollapsePlan&) const override {}
  void ensureErrors(const std::vector<const CollapsePlan*>& plans, ProgressReporter* progress = nullptr) override;
  CostAndError price(const CollapsePlan& plan) const override;
  std::vector<int> follow(const CollapsePlan&, int) override { return {}; }

private:
  const CollapseMesh& mesh_;
  TriangleErrorSource& errors_;
  bool areaWeighted_;
  DecimationStatistics& statistics_;
  std::unordered_map<uint64_t, double> cache_;  // by triangleKey
};

}  // namespace triwalk
