#include "core/selection/tile_partition.h"

#include "core/support/errors.h"

#include <algorithm>
#include <limits>

namespace triwalk {
namespace {

double distanceToRectangle(glm::dvec2 p, glm::dvec2 lower, glm::dvec2 upper) {
  const glm::dvec2 outside = glm::max(glm::max(lower - p, p - upper), glm::dvec2(0.0));
  return glm::length(outside);
}

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

}  // namespace

std::vector<TileCore> splitIntoCores(std::span<const glm::dvec2> positions, int count) {
  TRIWALK_CHECK(!positions.empty() && count >= 1, "tiles need samples");
  TileCore all;
  all.lower = glm::dvec2(std::numeric_limits<double>::max());
  all.upper = glm::dvec2(std::numeric_limits<double>::lowest());
  for (size_t i = 0; i < positions.size(); ++i) {
    all.lower = glm::min(all.lower, positions[i]);
    all.upper = glm::max(all.upper, positions[i]);
    all.members.push_back(int(i));
  }
  std::vector<TileCore> cores = {std::move(all)};
  std::vector<char> unsplittable(1, 0);
  while (int(cores.size()) < count) {
    size_t crowded = cores.size();
    for (size_t k = 0; k < cores.size(); ++k) {
      if (unsplittable[k]) continue;
      if (crowded == cores.size() || cores[k].members.size() > cores[crowded].members.size()) crowded = k;
    }
    if (crowded == cores.size()) break;
    const glm::dvec2 extent = cores[crowded].upper - cores[crowded].lower;
    const int longer = extent.x >= extent.y ? 0 : 1;
    TileCore low, high;
    if (!splitAcross(positions, cores[crowded], longer, low, high) &&
        !splitAcross(positions, cores[crowded], 1 - longer, low, high)) {
      unsplittable[crowded] = 1;
      continue;
    }
    cores[crowded] = std::move(low);
    cores.insert(cores.begin() + std::ptrdiff_t(crowded) + 1, std::move(high));
    unsplittable.insert(unsplittable.begin() + std::ptrdiff_t(crowded) + 1, 0);
  }
  return cores;
}

std::vector<Tile> tilesWithMargin(std::span<const glm::dvec2> positions, std::vector<TileCore> cores, double margin) {
  std::vector<Tile> tiles;
  tiles.reserve(cores.size());
  for (TileCore& core : cores) {
    Tile tile;
    for (size_t i = 0; i < positions.size(); ++i) {
      if (distanceToRectangle(positions[i], core.lower, core.upper) <= margin) tile.samples.push_back(int(i));
    }
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
      if (distanceToRectangle(positions[size_t(i)], other.lower, other.upper) <= distance) {
        band.push_back(i);
        break;
      }
    }
  }
  return band;
}

}  // namespace triwalk
