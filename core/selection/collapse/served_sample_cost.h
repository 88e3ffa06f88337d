#pragma once
// triwalk's cost: every dense sample that is not a reference is served by
// the triangle around it, as a walker standing there would be (outside the
// mesh, where its boundary shrank, by the best-ranked triangle, as eval
// and the viewer serve a position). A collapse costs the increase of the
// total reconstruction error over the samples its new triangles serve
// (those it frees included), so greedy on it removes, at each step, the
// reference whose loss the walkthrough feels least, measured where it is
// felt; the threshold applies to the mean error of those samples. Past
// pricedSamples, a stratified random subset prices it (sample_pricing.h).
// Because it prices what leaves the mesh, the boundary may shrink.

#include "core/geometry/line_of_sight_table.h"
#include "core/geometry/walkable_region.h"
#include "core/selection/collapse/collapse_mesh.h"
#include "core/selection/collapse/cost_model.h"
#include "core/selection/collapse/decimation_statistics.h"
#include "core/selection/triangle_error.h"

#include <set>
#include <unordered_map>

namespace triwalk {

class ServedSampleCost : public CostModel {
public:
  // Serves every sample from the dense mesh (its errors computed now, with
  // progress). weights: each sample's share of the walkthrough area, or
  // empty for equal shares; pricedSamples: 0 prices from all.
  ServedSampleCost(const ViewMesh& dense, const CollapseMesh& mesh, ReconstructionErrorSource& errors,
                   std::vector<double> weights, int pricedSamples, DecimationStatistics& statistics,
                   ProgressReporter* progress);

  void prepare(int a, int b, CollapsePlan& plan) const override;
  void ensureErrors(const std::vector<const CollapsePlan*>& plans, ProgressReporter* progress = nullptr) override;
  CostAndError price(const CollapsePlan& plan) const override;
  std::vector<int> follow(const CollapsePlan& plan, int firstAdded) override;

  // The weighted mean error of the samples that are not references, each
  // from the triangle serving it.
  double meanError() const;

private:
  struct SampleKey {
    uint64_t triangle;  // triangleKey
    int sample;
    bool operator==(const SampleKey&) const = default;
  };
  struct SampleKeyHash {
    size_t operator()(const SampleKey& key) const {
      return std::hash<uint64_t>()(key.triangle * 1000003u + uint64_t(key.sample));
    }
  };

  void choosePricedSamples(int a, int b, CollapsePlan& plan) const;
  const Triangle& servingTriangle(const CollapsePlan& plan, size_t i) const;
  ServingRank servingRank(const Triangle& triangle, int sample) const;
  double weightOf(int sample) const { return weights_.empty() ? 1.0 : weights_[size_t(sample)]; }
  // The reconstruction giving the error of the plan's i-th served sample.
  SampleReconstruction request(const CollapsePlan& plan, size_t i) const;
  void ensureSampleErrors(const std::vector<SampleReconstruction>& requests, ProgressReporter* progress = nullptr);
  double sampleError(const Triangle& triangle, int sample) const;

  const CollapseMesh& mesh_;
  ReconstructionErrorSource& errors_;
  std::vector<double> weights_;
  int pricedSamples_;
  DecimationStatistics& statistics_;
  // The triangle serving each sample (-1 for references), its error from
  // there, its rank there, and each triangle's samples.
  std::vector<int> home_;
  std::vector<double> homeError_;
  std::vector<ServingRank> homeRank_;  // {false, 0} inside the home triangle
  std::set<int> outside_;              // samples outside the mesh (where its boundary shrank)
  std::vector<std::vector<int>> served_;
  LineOfSightTable sight_;  // which samples see each other in the walkable region
  std::unordered_map<SampleKey, double, SampleKeyHash> cache_;
};

}  // namespace triwalk
