#include "core/selection/sample_pricing.h"

#include <algorithm>
#include <tuple>

namespace triwalk {

// SplitMix64's finaliser: well mixed, so that the lowest ranks of any set
// of samples are a uniform random subset of it.
uint64_t samplePricingRank(int sample) {
  uint64_t value = uint64_t(sample) + 0x9e3779b97f4a7c15ull;
  value = (value ^ (value >> 30)) * 0xbf58476d1ce4e5b9ull;
  value = (value ^ (value >> 27)) * 0x94d049bb133111ebull;
  return value ^ (value >> 31);
}

std::vector<PricedSample> stratifiedPricing(std::span<const int> samples, std::span<const int> strata, size_t limit,
                                            const std::function<double(int)>& weightOf) {
  std::vector<PricedSample> chosen;
  const size_t count = samples.size();
  if (limit == 0 || count <= limit) {
    for (size_t i = 0; i < count; ++i) chosen.push_back({int(i), 1.0});
    return chosen;
  }
  std::vector<std::tuple<int, uint64_t, int>> ordered;  // (stratum, rank, index): strata apart, lowest rank first
  ordered.reserve(count);
  for (size_t i = 0; i < count; ++i) ordered.emplace_back(strata[i], samplePricingRank(samples[i]), int(i));
  std::sort(ordered.begin(), ordered.end());
  for (size_t begin = 0; begin < count;) {
    size_t end = begin;
    while (end < count && std::get<0>(ordered[end]) == std::get<0>(ordered[begin])) ++end;
    const size_t members = end - begin;
    const size_t keep = std::max<size_t>(1, (limit * members + count - 1) / count);
    double all = 0.0, kept = 0.0;
    for (size_t k = 0; k < members; ++k) {
      const double weight = weightOf(samples[size_t(std::get<2>(ordered[begin + k]))]);
      all += weight;
      if (k < keep) kept += weight;
    }
    for (size_t k = 0; k < std::min(keep, members); ++k) {
      chosen.push_back({std::get<2>(ordered[begin + k]), kept > 0.0 ? all / kept : 0.0});
    }
    begin = end;
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

}  // namespace triwalk
