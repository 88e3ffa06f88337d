#pragma once
// A collapse worked out on the current mesh but not made: which triangles
// go, which come, and (under the served-sample cost) which dense samples
// change their serving triangle. The rules fill the first part, the cost
// the second; the engine ranks plans and makes the cheapest.

#include "core/geometry/planar_geometry.h"
#include "core/geometry/view_mesh.h"
#include "core/selection/collapse/collapse_log.h"
#include "core/selection/sample_pricing.h"

#include <vector>

namespace triwalk {

// The served-sample cost's part of a plan (empty under the centroid cost).
struct ServedChange {
  std::vector<int> samples;       // whose serving triangle changes, sorted
  std::vector<int> servedBy;      // per sample: index into added, or -1 - id of an existing triangle
  std::vector<ServingRank> rank;  // of that triangle for the sample ({false, 0} inside)
  // Of samples, those whose errors price the collapse (index into samples,
  // sorted), each with the served weight it stands for over its own.
  std::vector<PricedSample> priced;
};

struct CollapsePlan {
  int placement = -1;
  PlacementKind kind = PlacementKind::First;
  std::vector<int> removed;     // triangle ids, sorted
  std::vector<Triangle> added;  // canonical, sorted
  ServedChange served;
};

}  // namespace triwalk
