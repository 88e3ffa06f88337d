#pragma once
// An automatic walkable area for scenes that do not state one: positions
// on a grid at eye height are probed with small panoramas, and a position
// counts as walkable when its view is enclosed (almost every direction
// meets a surface: inside, not outdoors or outside the level), nothing is
// within reach of the head, and a floor lies at eye height below. The
// largest rectangle of walkable positions becomes the area. Floors come
// from the level's spawn points where it has them, else from the largest
// upward-facing surface.

#include "render/capture/panorama_capturer.h"
#include "render/scene/scene.h"

#include <span>
#include <string>

namespace triwalk {

struct WalkableAreaProposal {
  glm::vec4 area{0.0f};  // x0, y0, x1, y1, metres
  float floorZ = 0.0f;
  int walkableCells = 0;
  int probedCells = 0;
  std::string reason;    // what was chosen and why, for the report
};

// Needs a current GL context. eyeHeight in metres above the floor;
// spacing is the probe grid's. Throws InputError when nothing is walkable.
WalkableAreaProposal proposeWalkableArea(const Scene& scene, float eyeHeight, float spacing, const std::string& subject,
                                         bool quiet = false);

// The height of the largest upward-facing surface area (the main floor).
float dominantFloorHeight(const Scene& scene);

}  // namespace triwalk
