#pragma once
// A procedural floor of a building, in the built-in scene family: rooms on
// a grid, corridors between every two rows of rooms, a spine corridor
// joining them on the west side, doors from each room to its corridor and
// some between neighbours, and furniture (tables and crates a walker sees
// over, cabinets against the walls), all deterministic from a seed. Its
// size is a parameter, so captures of 450 to 28,800 samples at one
// density are the test bed of how cost grows with a capture; the levels
// and the house stay the test bed of quality.
//
// `--scene builtin-floor:CxR[:SEED]`: C rooms along x, R rows of rooms.

#include "core/geometry/walkable_region.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace triwalk {

struct FloorPlanSize {
  int columns = 0;
  int rows = 0;
  unsigned seed = 1;
};

// The size a scene spec asks for: nullopt unless spec starts with
// "builtin-floor"; InputError naming --scene for a malformed one (sizes
// 1 to 64 rooms a side).
std::optional<FloorPlanSize> parseFloorPlanSpec(const std::string& spec);

struct FloorPlan {
  nlohmann::json description;  // a scene description (docs/SCENE_FORMAT.md)
  WalkableRegion region;       // rooms, corridors and doorways, 0.3 m clear of walls and cabinets
  float sampleSpacing = 0.0f;  // metres: the built-in capture's density, about 9 samples a square metre
};

// The floor; materials, sky and ambient light are the built-in scene's
// (builtinDescription), so the family looks alike.
FloorPlan makeFloorPlan(const FloorPlanSize& size, const nlohmann::json& builtinDescription);

}  // namespace triwalk
