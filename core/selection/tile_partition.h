#pragma once
// Cutting a capture into tiles for tiled decimation (docs/DESIGN.md,
// "Tiled selection"). Each tile has a core, a rectangle whose samples it
// decides, and a margin around it, whose samples it decimates too but
// whose references it drops: a reference near a core's border is chosen
// knowing the neighbours a walker there would also use. The cores are
// cut by median splits of the samples, the core whose tile holds the most
// samples split across its longer side, so that tiles hold nearly equal
// counts however the samples are spread (a corridor, a hall, a building
// of rooms) and wherever the margins fall (a tile inside a floor has
// margin on four sides, one at its corner on two).

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace triwalk {

struct TileCore {
  glm::dvec2 lower{0.0}, upper{0.0};  // the rectangle; its samples are members
  std::vector<int> members;           // sample indices, sorted
};

struct Tile {
  TileCore core;
  std::vector<int> samples;  // core and margin: sample indices, sorted
};

// When splitting stops: at `count` cores if count > 0, else when every
// tile (core and margin) holds at most mostTileSamples samples.
struct CoreSplitStop {
  int count = 0;
  size_t mostTileSamples = 0;
};

// Splits the samples into cores: the core whose tile (the core and the
// samples within `margin` of it) holds the most samples, the first on a
// tie, is split at the median across its longer side, between two distinct
// coordinates, so no sample lies on a border; until `stop`, or until no
// core can be split (samples that share a position). Deterministic.
std::vector<TileCore> splitIntoCores(std::span<const glm::dvec2> positions, double margin, CoreSplitStop stop);

// How far p lies outside the core's rectangle (0 inside it).
double distanceToCore(glm::dvec2 p, const TileCore& core);

// Each core with the samples within `margin` metres of its rectangle.
std::vector<Tile> tilesWithMargin(std::span<const glm::dvec2> positions, std::vector<TileCore> cores, double margin);

// The samples within `distance` of a core's border inside it (sorted): the band a
// seam pass may change.
std::vector<int> bandMembers(std::span<const glm::dvec2> positions, const TileCore& core, double distance,
                             const std::vector<TileCore>& cores);

}  // namespace triwalk
