// The stratified subsets that price collapses and refinement moves: exact
// outputs on a handful of samples.

#include "core/selection/sample_pricing.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

namespace triwalk {

TEST_CASE("stratified pricing: all at scale 1 up to the limit, else each triangle's share of lowest rank") {
  const std::vector<int> samples = {10, 11, 12, 13, 14, 15, 16, 17};
  const std::vector<int> strata = {0, 0, 0, 0, 0, 0, 1, 1};  // six samples in one triangle, two in another
  auto unit = [](int) { return 1.0; };

  for (size_t limit : {size_t(0), size_t(8), size_t(20)}) {
    const std::vector<PricedSample> all = stratifiedPricing(samples, strata, limit, unit);
    REQUIRE(all.size() == samples.size());
    for (size_t i = 0; i < all.size(); ++i) {
      CHECK(all[i].index == int(i));
      CHECK(all[i].scale == 1.0);
    }
  }

  // Limit 4 of 8: the first triangle gets ceil(4 x 6 / 8) = 3, the second
  // ceil(4 x 2 / 8) = 1, each the samples of lowest rank.
  const std::vector<PricedSample> priced = stratifiedPricing(samples, strata, 4, unit);
  REQUIRE(priced.size() == 4);
  CHECK(std::is_sorted(priced.begin(), priced.end(),
                       [](const PricedSample& x, const PricedSample& y) { return x.index < y.index; }));
  std::vector<std::pair<uint64_t, int>> first, second;
  for (int i = 0; i < 6; ++i) first.emplace_back(samplePricingRank(samples[size_t(i)]), i);
  for (int i = 6; i < 8; ++i) second.emplace_back(samplePricingRank(samples[size_t(i)]), i);
  std::sort(first.begin(), first.end());
  std::sort(second.begin(), second.end());
  std::vector<int> expected = {first[0].second, first[1].second, first[2].second, second[0].second};
  std::sort(expected.begin(), expected.end());
  for (size_t k = 0; k < priced.size(); ++k) {
    CHECK(priced[k].index == expected[k]);
    CHECK(priced[k].scale == doctest::Approx(priced[k].index < 6 ? 6.0 / 3.0 : 2.0 / 1.0));
  }

  // Weights: a priced sample stands for its triangle's weight over the
  // weight of those priced.
  auto weights = [](int sample) { return sample == 16 ? 3.0 : 1.0; };
  const std::vector<PricedSample> weighted = stratifiedPricing(samples, strata, 4, weights);
  REQUIRE(weighted.size() == 4);
  CHECK(weighted.back().index == second[0].second);
  CHECK(weighted.back().scale == doctest::Approx(4.0 / weights(samples[size_t(second[0].second)])));
}

}  // namespace triwalk
