#pragma once
// The automatic walkable region of a scene that does not state one: a
// flood fill over a grid of floor cells, from seeds, through positions a
// person could stand at. A cell is walkable when a small panorama at eye
// height above its centre is enclosed (almost every direction meets a
// surface: inside, not outdoors or outside the level), nothing is within
// reach of the head (so no wall runs between two walkable neighbours: the
// clearance is at least the cell size), and a floor lies at eye height
// below. Only cells the fill reaches are probed. The reached cells become
// a region of polygons with holes (core/geometry/cell_region.h).

#include "core/geometry/walkable_region.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace triwalk {

struct RegionSearchOptions {
  float eyeHeight = 1.6f;  // metres above the floor
  float cellSize = 0.25f;  // metres; at most twice the head clearance (0.25 m)
  // Seeds on the floor plane (--start). Default: the level's spawn points,
  // else the centre of the scene's bounds.
  std::vector<glm::vec2> starts;
  bool quiet = false;
};

struct WalkableRegionProposal {
  WalkableRegion region;
  float floorZ = 0.0f;
  int parts = 0;
  int walkableCells = 0;
  int probedCells = 0;
  std::string reason;  // how it was found, for the report
};

// Needs a current GL context. Shows progress and stops on Ctrl-C
// (Interrupted). Throws InputError naming subject when no seed reaches a
// walkable position.
WalkableRegionProposal proposeWalkableRegion(const Scene& scene, const RegionSearchOptions& options,
                                             const std::string& subject);

// The height of the largest horizontal surface area (the main floor).
float dominantFloorHeight(const Scene& scene);

// The floor under a given region: the height whose upward-facing
// horizontal surfaces cover the most of the region (ties: the lower). A
// level's largest floor may lie elsewhere, or be a roof above the region.
// The scene's dominant floor when nothing horizontal lies under it.
float floorHeightUnder(const Scene& scene, const WalkableRegion& region);

}  // namespace triwalk
