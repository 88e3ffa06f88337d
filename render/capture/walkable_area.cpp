#include "render/capture/walkable_area.h"

#include "core/support/errors.h"
#include "core/support/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace triwalk {

namespace {

constexpr float kSpawnAboveFloor = 0.61f;  // Quake 3 spawn origins stand 24 units above the floor
constexpr float kSpawnReach = 8.0f;        // metres probed around a spawn point

struct Rectangle {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  int cells() const { return (x1 - x0 + 1) * (y1 - y0 + 1); }
};

// Largest all-true rectangle of a grid (histogram method, row by row)
// whose sides differ by at most a factor 3: a long corridor makes a poor
// walkthrough area (paths across it would be a few samples long).
Rectangle largestRectangle(const std::vector<std::vector<bool>>& walkable) {
  Rectangle best;
  if (walkable.empty()) return best;
  const int rows = int(walkable.size()), columns = int(walkable[0].size());
  std::vector<int> heights(size_t(columns), 0);
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < columns; ++x) heights[size_t(x)] = walkable[size_t(y)][size_t(x)] ? heights[size_t(x)] + 1 : 0;
    for (int x = 0; x < columns; ++x) {
      int height = heights[size_t(x)];
      for (int right = x; right < columns && height > 0; ++right) {
        height = std::min(height, heights[size_t(right)]);
        const int width = right - x + 1;
        const Rectangle candidate{x, y - std::min(height, 3 * width) + 1, right, y};
        if (width <= 3 * height && candidate.cells() > best.cells()) best = candidate;
      }
    }
  }
  return best;
}

bool walkableView(const Panorama& panorama, float eyeHeight) {
  size_t finite = 0;
  float nearest = INFINITY;
  for (float d : panorama.distance.pixels) {
    finite += std::isfinite(d);
    nearest = std::min(nearest, d);
  }
  const float down = panorama.distance.at(panorama.width() / 2, panorama.height() - 1);
  return double(finite) >= 0.95 * double(panorama.distance.pixelCount()) && nearest >= 0.25f &&
         std::abs(down - eyeHeight) <= 0.2f * eyeHeight;
}

}  // namespace

float dominantFloorHeight(const Scene& scene) {
  std::map<int, double> areaByHeight;  // 5 cm bins
  for (const SceneMesh& mesh : scene.meshes) {
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const glm::vec3 a = mesh.vertices[mesh.indices[i]].position, b = mesh.vertices[mesh.indices[i + 1]].position,
                      c = mesh.vertices[mesh.indices[i + 2]].position;
      const glm::vec3 normal = glm::cross(b - a, c - a);
      const float area = 0.5f * glm::length(normal);
      if (area <= 0.0f || std::abs(normal.z) < 0.95f * 2.0f * area) continue;  // not horizontal
      areaByHeight[int(std::lround((a.z + b.z + c.z) / 3.0f / 0.05f))] += area;
    }
  }
  if (areaByHeight.empty()) return 0.0f;
  const auto largest = std::max_element(areaByHeight.begin(), areaByHeight.end(),
                                        [](const auto& x, const auto& y) { return x.second < y.second; });
  return float(largest->first) * 0.05f;
}

WalkableAreaProposal proposeWalkableArea(const Scene& scene, float eyeHeight, float spacing, const std::string& subject,
                                         bool quiet) {
  glm::vec3 lower, upper;
  scene.bounds(lower, upper);
  // Candidate floors: each spawn point's, or the dominant one.
  std::vector<float> floors;
  for (const glm::vec3& spawn : scene.spawnPoints) {
    const float floor = spawn.z - kSpawnAboveFloor;
    if (std::none_of(floors.begin(), floors.end(), [&](float f) { return std::abs(f - floor) < 0.3f; })) floors.push_back(floor);
  }
  const bool fromSpawns = !floors.empty();
  if (!fromSpawns) floors.push_back(dominantFloorHeight(scene));

  PanoramaCapturer capturer(scene, 32, 16);
  const int columns = std::max(1, int((upper.x - lower.x) / spacing)), rows = std::max(1, int((upper.y - lower.y) / spacing));
  const auto positionAt = [&](int x, int y, float floor) {
    return glm::vec3(lower.x + (float(x) + 0.5f) * spacing, lower.y + (float(y) + 0.5f) * spacing, floor + eyeHeight);
  };
  // On a spawn floor, only around that floor's spawn points.
  const auto worthProbing = [&](glm::vec3 position, float floor) {
    return !fromSpawns || std::any_of(scene.spawnPoints.begin(), scene.spawnPoints.end(), [&](const glm::vec3& spawn) {
      return std::abs(spawn.z - kSpawnAboveFloor - floor) < 0.3f && glm::length(glm::vec2(spawn - position)) < kSpawnReach;
    });
  };
  // The cells each floor probes, listed first so that progress knows the total.
  std::vector<std::vector<glm::ivec2>> cellsToProbe(floors.size());
  size_t toProbe = 0;
  for (size_t f = 0; f < floors.size(); ++f) {
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < columns; ++x) {
        if (worthProbing(positionAt(x, y, floors[f]), floors[f])) cellsToProbe[f].emplace_back(x, y);
      }
    }
    toProbe += cellsToProbe[f].size();
  }
  // A level without spawn points is probed over its whole bounding box:
  // minutes on a large one, so it shows progress and stops on Ctrl-C.
  InterruptScope interruptScope;
  ProgressReporter progress("find walkable area: positions probed", toProbe, quiet);
  WalkableAreaProposal best;
  int bestCells = 0;
  for (size_t f = 0; f < floors.size(); ++f) {
    const float floor = floors[f];
    std::vector<std::vector<bool>> walkable(size_t(rows), std::vector<bool>(size_t(columns), false));
    int count = 0;
    for (const glm::ivec2 cell : cellsToProbe[f]) {
      throwIfInterrupted();
      const bool ok = walkableView(capturer.capture(positionAt(cell.x, cell.y, floor)), eyeHeight);
      progress.advance();
      walkable[size_t(cell.y)][size_t(cell.x)] = ok;
      count += ok;
    }
    const int probed = int(cellsToProbe[f].size());
    const Rectangle rectangle = largestRectangle(walkable);
    // At least 2 x 2 positions: the area must have a width and a depth.
    if (rectangle.x1 <= rectangle.x0 || rectangle.y1 <= rectangle.y0 || rectangle.cells() <= bestCells) continue;
    bestCells = rectangle.cells();
    best.area = {lower.x + float(rectangle.x0) * spacing + 0.5f * spacing, lower.y + float(rectangle.y0) * spacing + 0.5f * spacing,
                 lower.x + float(rectangle.x1) * spacing + 0.5f * spacing, lower.y + float(rectangle.y1) * spacing + 0.5f * spacing};
    best.floorZ = floor;
    best.walkableCells = count;
    best.probedCells = probed;
  }
  progress.finish();
  if (bestCells == 0) {
    throw InputError(subject, "no walkable area found automatically (no enclosed positions with a floor at eye height); "
                              "give --area and --eye-height");
  }
  char reason[256];
  std::snprintf(reason, sizeof reason,
                "automatic walkable area [%.2f, %.2f] x [%.2f, %.2f] m on the floor at z = %.2f m (%s): %d of %d probed "
                "positions are enclosed with a floor at eye height, this is their largest rectangle",
                best.area.x, best.area.z, best.area.y, best.area.w, best.floorZ,
                fromSpawns ? "from the level's spawn points" : "the largest horizontal surface", best.walkableCells,
                best.probedCells);
  best.reason = reason;
  return best;
}

}  // namespace triwalk
