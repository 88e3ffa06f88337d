#include "core/selection/tile_partition.h"

#include "core/support/errors.h"

#include <algorithm>
#include <limits>

namespace triwalk {

double distanceToCore(glm::dvec2 p, const TileCore& core) {
  return glm::length(glm::max(glm::max(core.lower - p, p - core.upper), glm::dvec2(0.0)));
}

namespace {

// Splits core across axis between two distinct coordinates at its median;
// false if all its samples share the coordinate.
bool splitAcross(std::span<const glm::dvec2> positions, const TileCore& core, int axis, TileCore& low, TileCore& high) {
  std::vector<double> values;
  values.reserve(core.members.size());
  for (int i : core.members) values.push_back(positions[size_t(i)][axis]);
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  if (values.size() < 2) return false;
  // The distinct coordinate that the median sample has, and the one below it
  // (or above, at the bottom): the border runs halfway between them.
  std::vector<double> all;
  for (int i : core.members) all.push_back(positions[size_t(i)][axis]);
  std::nth_element(all.begin(), all.begin() + std::ptrdiff_t(all.size() / 2), all.end());
  const double median = all[all.size() / 2];
  auto at = std::lower_bound(values.begin(), values.end(), median);
  if (at == values.begin()) ++at;
  const double border = 0.5 * (*(at - 1) + *at);
  low = high = TileCore{core.lower, core.upper, {}};
  low.upper[axis] = border;
  high.lower[axis] = border;
  for (int i : core.members) (positions[size_t(i)][axis] < border ? low : high).members.push_back(i);
  return true;
}

// The samples ordered along x: those near a rectangle are found among the
// ones in its x range, not by visiting the whole capture for every tile.
class SamplesAlongX {
public:
  explicit SamplesAlongX(std::span<const glm::dvec2> positions) : positions_(positions), order_(positions.size()) {
    for (size_t i = 0; i < order_.size(); ++i) order_[i] = int(i);
    std::sort(order_.begin(), order_.end(), [&](int a, int b) {
      return std::pair(positions[size_t(a)].x, a) < std::pair(positions[size_t(b)].x, b);
    });
  }

  // Calls visit(i) for each sample within `distance` of the core's rectangle, in no set order.
  template <class Visit>
  void forEachNear(const TileCore& core, double distance, Visit visit) const {
    auto first = std::partition_point(order_.begin(), order_.end(),
                                      [&](int i) { return positions_[size_t(i)].x < core.lower.x - distance; });
    for (auto at = first; at != order_.end() && positions_[size_t(*at)].x <= core.upper.x + distance; ++at) {
      if (distanceToCore(positions_[size_t(*at)], core) <= distance) visit(*at);
    }
  }

  size_t countNear(const TileCore& core, double distance) const {
    size_t count = 0;
    forEachNear(core, distance, [&](int) { ++count; });
    return count;
  }

private:
  std::span<const glm::dvec2> positions_;
  std::vector<int> order_;
};

}  // namespace

std::vector<TileCore> splitIntoCores(std::span<const glm::dvec2> positions, double margin, CoreSplitStop stop) {
  TRIWALK_CHECK(!positions.empty() && (stop.count >= 1 || stop.mostTileSamples >= 1), "tiles need samples and a stop");
  const SamplesAlongX alongX(positions);
  TileCore all;
  all.lower = glm::dvec2(std::numeric_limits<double>::max());
  all.upper = glm::dvec2(std::numeric_limits<double>::lowest());
  for (size_t i = 0; i < positions.size(); ++i) {
    all.lower = glm::min(all.lower, positions[i]);
    all.upper = glm::max(all.upper, positions[i]);
    all.members.push_back(int(i));
  }
  std::vector<TileCore> cores = {std::move(all)};
  std::vector<size_t> tileSamples = {positions.size()};
  std::vector<char> unsplittable(1, 0);
  // With a bound, only a tile above it is split.
  auto splittable = [&](size_t k) {
    return !unsplittable[k] && (stop.count > 0 || tileSamples[k] > stop.mostTileSamples);
  };
  while (stop.count == 0 || int(cores.size()) < stop.count) {
    size_t largest = cores.size();
    for (size_t k = 0; k < cores.size(); ++k) {
      if (!splittable(k)) continue;
      if (largest == cores.size() || tileSamples[k] > tileSamples[largest]) largest = k;
    }
    if (largest == cores.size()) break;
    const glm::dvec2 extent = cores[largest].upper - cores[largest].lower;
    const int longer = extent.x >= extent.y ? 0 : 1;
    TileCore low, high;
    if (!splitAcross(positions, cores[largest], longer, low, high) &&
        !splitAcross(positions, cores[largest], 1 - longer, low, high)) {
      unsplittable[largest] = 1;
      continue;
    }
    const auto after = std::ptrdiff_t(largest) + 1;
    tileSamples[largest] = alongX.countNear(low, margin);
    tileSamples.insert(tileSamples.begin() + after, alongX.countNear(high, margin));
    cores[largest] = std::move(low);
    cores.insert(cores.begin() + after, std::move(high));
    unsplittable.insert(unsplittable.begin() + after, 0);
  }
  return cores;
}

std::vector<Tile> tilesWithMargin(std::span<const glm::dvec2> positions, std::vector<TileCore> cores, double margin) {
  const SamplesAlongX alongX(positions);
  std::vector<Tile> tiles;
  tiles.reserve(cores.size());
  for (TileCore& core : cores) {
    Tile tile;
    alongX.forEachNear(core, margin, [&](int i) { tile.samples.push_back(i); });
    std::sort(tile.samples.begin(), tile.samples.end());
    tile.core = std::move(core);
    tiles.push_back(std::move(tile));
  }
  return tiles;
}

std::vector<int> bandMembers(std::span<const glm::dvec2> positions, const TileCore& core, double distance,
                             const std::vector<TileCore>& cores) {
  std::vector<int> band;
  for (int i : core.members) {
    for (const TileCore& other : cores) {
      if (&other == &core) continue;
      if (distanceToCore(positions[size_t(i)], other) <= distance) {
        band.push_back(i);
        break;
      }
    }
  }
  return band;
}

}  // namespace triwalk
