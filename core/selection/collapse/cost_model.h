#pragma once
// What a collapse costs: the engine asks a cost to complete each valid
// plan with what pricing it needs, to compute the errors of a batch of
// plans together (in parallel, through its cache), to price each plan,
// and to follow each collapse made. Two costs: the paper's
// (centroid_cost.h) and the served samples' (served_sample_cost.h).

#include "core/selection/collapse/collapse_plan.h"

#include <vector>

namespace triwalk {

class ProgressReporter;

struct CostAndError {
  double cost = 0.0;   // what ranks the collapse (lower first)
  double error = 0.0;  // what the error threshold is compared with
};

class CostModel {
public:
  virtual ~CostModel() = default;
  // Completes a valid plan of the collapse of edge (a, b).
  virtual void prepare(int a, int b, CollapsePlan& plan) const = 0;
  // Computes every error the plans' prices need that is not cached.
  virtual void ensureErrors(const std::vector<const CollapsePlan*>& plans, ProgressReporter* progress = nullptr) = 0;
  virtual CostAndError price(const CollapsePlan& plan) const = 0;
  // After the mesh made the plan (its added triangles from id firstAdded):
  // the existing triangles whose share of the cost changed, so that the
  // edges around them are priced again.
  virtual std::vector<int> follow(const CollapsePlan& plan, int firstAdded) = 0;
};

}  // namespace triwalk
