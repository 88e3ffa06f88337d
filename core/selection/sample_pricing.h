#pragma once
// Pricing a change of the selection on a subset of the dense samples it
// changes: the decimator's collapses and the refinement's candidate moves
// both cost the change of the reconstruction error over the samples whose
// serving triangle changes, and on a dense capture a late collapse or a
// move of a reference among few serves hundreds. A stratified random
// subset estimates that change at a bounded number of errors.

#include <compare>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace triwalk {

// A fixed pseudo-random rank of a sample (the same on every machine and
// run): the subsets are the samples of lowest rank, so they are uniform
// random samples that overlap from one candidate to the next, and the
// errors one candidate computed serve the next.
uint64_t samplePricingRank(int sample);

struct PricedSample {
  int index = 0;       // into the samples given
  double scale = 1.0;  // the weight it stands for over its own weight
  auto operator<=>(const PricedSample&) const = default;  // by index first
};

// Of samples[i], each in stratum strata[i] (the triangle that serves it
// after the change), about `limit`: each stratum gets its share of the
// limit (at least one), the samples of lowest rank, each scaled to stand
// for the weight of its whole stratum. All of them at scale 1 when limit
// is 0 or the samples are not more than it. Sorted by index.
std::vector<PricedSample> stratifiedPricing(std::span<const int> samples, std::span<const int> strata, size_t limit,
                                            const std::function<double(int)>& weightOf);

}  // namespace triwalk
