#include "render/capture/walkable_area.h"

#include "core/geometry/cell_region.h"
#include "core/geometry/planar_geometry.h"
#include "core/support/errors.h"
#include "render/capture/panorama_capturer.h"
#include "core/support/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

namespace triwalk {

namespace {

constexpr float kSpawnAboveFloor = 0.61f;  // Quake 3 spawn origins stand 24 units above the floor

bool walkableView(const ScalarImage& distance, float eyeHeight) {
  size_t finite = 0;
  float nearest = INFINITY;
  for (float d : distance.pixels) {
    finite += std::isfinite(d);
    nearest = std::min(nearest, d);
  }
  const float down = distance.at(distance.width / 2, distance.height - 1);
  return double(finite) >= 0.95 * double(distance.pixelCount()) && nearest >= 0.25f &&
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

float floorHeightUnder(const Scene& scene, const WalkableRegion& region) {
  // Points inside the region, at most about 4096, each counted once per
  // 5 cm height bin whose upward surfaces cover it.
  glm::dvec2 lower, upper;
  region.bounds(lower, upper);
  const double step = std::max(0.25, std::sqrt(region.area() / 4096.0));
  const int columns = int(std::ceil((upper.x - lower.x) / step)), rows = int(std::ceil((upper.y - lower.y) / step));
  auto pointAt = [&](int x, int y) { return lower + step * glm::dvec2(x + 0.5, y + 0.5); };
  std::vector<uint8_t> inside(size_t(columns) * size_t(rows));
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < columns; ++x) inside[size_t(y) * size_t(columns) + size_t(x)] = region.contains(pointAt(x, y));
  }
  std::map<int, std::vector<uint8_t>> coveredByHeight;
  for (const SceneMesh& mesh : scene.meshes) {
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const SceneVertex &a = mesh.vertices[mesh.indices[i]], &b = mesh.vertices[mesh.indices[i + 1]],
                        &c = mesh.vertices[mesh.indices[i + 2]];
      const glm::vec3 normal = glm::cross(b.position - a.position, c.position - a.position);
      const float length = glm::length(normal);
      if (length <= 0.0f || std::abs(normal.z) < 0.95f * length) continue;  // not horizontal
      // Facing from the shading normals, which importers keep consistent
      // even where the winding is not.
      if ((a.normal + b.normal + c.normal).z <= 0.0f) continue;
      glm::dvec2 p0(a.position), p1(b.position), p2(c.position);
      if (normal.z < 0.0f) std::swap(p1, p2);  // counter-clockwise seen from above
      const glm::dvec2 low = glm::min(p0, glm::min(p1, p2)), high = glm::max(p0, glm::max(p1, p2));
      const int x0 = std::max(0, int(std::floor((low.x - lower.x) / step - 0.5)));
      const int x1 = std::min(columns - 1, int(std::ceil((high.x - lower.x) / step - 0.5)));
      const int y0 = std::max(0, int(std::floor((low.y - lower.y) / step - 0.5)));
      const int y1 = std::min(rows - 1, int(std::ceil((high.y - lower.y) / step - 0.5)));
      if (x0 > x1 || y0 > y1) continue;
      const int bin = int(std::lround((a.position.z + b.position.z + c.position.z) / 3.0f / 0.05f));
      std::vector<uint8_t>& covered = coveredByHeight[bin];
      covered.resize(inside.size());
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
          const size_t cell = size_t(y) * size_t(columns) + size_t(x);
          if (inside[cell] && distanceToTriangle(p0, p1, p2, pointAt(x, y)) == 0.0) covered[cell] = 1;
        }
      }
    }
  }
  int bestBin = 0;
  size_t bestCount = 0;
  for (const auto& [bin, covered] : coveredByHeight) {  // ascending heights: ties keep the lower
    const size_t count = size_t(std::count(covered.begin(), covered.end(), uint8_t(1)));
    if (count > bestCount) bestCount = count, bestBin = bin;
  }
  return bestCount > 0 ? float(bestBin) * 0.05f : dominantFloorHeight(scene);
}

namespace {

struct Seed {
  int floor = 0;  // index into the candidate floors
  glm::vec2 position{0.0f};
  const char* origin = "";
};

// Probes cells on demand, once each, per floor.
class CellProber {
public:
  CellProber(const Scene& scene, const CellGrid& grid, const std::vector<float>& floors, float eyeHeight,
             ProgressReporter& progress)
      : capturer_(scene, 32, 16), grid_(grid), floors_(floors), eyeHeight_(eyeHeight), progress_(progress),
        state_(floors.size(), std::vector<int8_t>(grid.marked.size(), -1)) {}

  bool walkable(int floor, int x, int y) {
    if (x < 0 || y < 0 || x >= grid_.columns || y >= grid_.rows) return false;
    int8_t& state = state_[size_t(floor)][size_t(y) * size_t(grid_.columns) + size_t(x)];
    if (state < 0) {
      throwIfInterrupted();
      const glm::dvec2 centre = grid_.centre(x, y);
      state = walkableView(
          capturer_.captureDistance(glm::vec3(centre.x, centre.y, floors_[size_t(floor)] + eyeHeight_)), eyeHeight_);
      ++probed_;
      progress_.advance();
    }
    return state == 1;
  }
  int probed() const { return probed_; }

private:
  PanoramaCapturer capturer_;
  const CellGrid& grid_;
  const std::vector<float>& floors_;
  float eyeHeight_;
  ProgressReporter& progress_;
  std::vector<std::vector<int8_t>> state_;  // -1 unknown, 0 no, 1 walkable
  int probed_ = 0;
};

constexpr float kSeedReach = 2.0f;  // metres searched around a seed that is not walkable itself

}  // namespace

WalkableRegionProposal proposeWalkableRegion(const Scene& scene, const RegionSearchOptions& options,
                                             const std::string& subject) {
  glm::vec3 lower, upper;
  scene.bounds(lower, upper);
  const double cell = options.cellSize;
  CellGrid grid(glm::dvec2(lower.x, lower.y), cell, std::max(1, int(std::ceil((upper.x - lower.x) / cell))),
                std::max(1, int(std::ceil((upper.y - lower.y) / cell))));

  // Candidate floors: each spawn point's, and the dominant one.
  std::vector<float> floors;
  const auto floorIndex = [&](float floor) {
    for (size_t f = 0; f < floors.size(); ++f) {
      if (std::abs(floors[f] - floor) < 0.3f) return int(f);
    }
    floors.push_back(floor);
    return int(floors.size()) - 1;
  };
  std::vector<Seed> seeds;
  const int dominant = floorIndex(dominantFloorHeight(scene));
  if (!options.starts.empty()) {
    // A start is tried on every floor the scene has; the fill keeps the floors it walks on.
    for (const glm::vec3& spawn : scene.spawnPoints) floorIndex(spawn.z - kSpawnAboveFloor);
    for (const glm::vec2 start : options.starts) {
      for (int f = 0; f < int(floors.size()); ++f) seeds.push_back({f, start, "--start"});
    }
  } else if (!scene.spawnPoints.empty()) {
    for (const glm::vec3& spawn : scene.spawnPoints) seeds.push_back({floorIndex(spawn.z - kSpawnAboveFloor), glm::vec2(spawn), "spawn points"});
  } else {
    seeds.push_back({dominant, 0.5f * glm::vec2(lower + upper), "the scene's centre"});
  }

  // The probes see the scene without its door leaves: a closed door joins
  // two rooms as an open one would.
  const Scene solid = withDoorsOpen(scene);
  InterruptScope interruptScope;
  ProgressReporter progress("find walkable region: cells probed", 0, options.quiet);
  CellProber prober(solid, grid, floors, options.eyeHeight, progress);
  std::vector<CellGrid> reached(floors.size(), CellGrid(grid.origin, cell, grid.columns, grid.rows));
  std::vector<glm::ivec2> queue;
  for (const Seed& seed : seeds) {
    CellGrid& fill = reached[size_t(seed.floor)];
    const glm::ivec2 home(glm::floor((glm::dvec2(seed.position) - grid.origin) / cell));
    // The seed's own cell, else the nearest walkable one within reach (rings outward).
    std::optional<glm::ivec2> start;
    const int reach = int(std::ceil(kSeedReach / cell));
    for (int ring = 0; ring <= reach && !start; ++ring) {
      for (int y = home.y - ring; y <= home.y + ring && !start; ++y) {
        for (int x = home.x - ring; x <= home.x + ring && !start; ++x) {
          if (std::max(std::abs(x - home.x), std::abs(y - home.y)) != ring) continue;
          if (prober.walkable(seed.floor, x, y)) start = glm::ivec2(x, y);
        }
      }
    }
    if (!start || fill.at(start->x, start->y)) continue;  // none, or already reached from another seed
    fill.set(start->x, start->y, true);
    queue.assign(1, *start);
    for (size_t next = 0; next < queue.size(); ++next) {
      for (const glm::ivec2 step : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
        const glm::ivec2 neighbour = queue[next] + step;
        if (fill.at(neighbour.x, neighbour.y) || !prober.walkable(seed.floor, neighbour.x, neighbour.y)) continue;
        fill.set(neighbour.x, neighbour.y, true);
        queue.push_back(neighbour);
      }
      if (next % 64 == 0) {
        progress.setStatus(std::to_string(fill.count()) + " walkable, " + std::to_string(queue.size() - next) + " to expand");
      }
    }
  }
  progress.finish();

  // Per floor: parts without corner contacts; parts under a tenth of the
  // largest (a ledge, a nook behind a pillar) are dropped. The floor with
  // the most walkable area wins.
  WalkableRegionProposal best;
  int bestCells = 0, bestFloor = -1;
  CellGrid bestGrid;
  for (size_t f = 0; f < floors.size(); ++f) {
    CellGrid fill = reached[f];
    removeCornerContacts(fill);
    int partCount = 0;
    const std::vector<int> labels = connectedParts(fill, partCount);
    std::vector<int> sizes(size_t(partCount), 0);
    for (int label : labels) {
      if (label >= 0) ++sizes[size_t(label)];
    }
    const int largest = sizes.empty() ? 0 : *std::max_element(sizes.begin(), sizes.end());
    int kept = 0, keptParts = 0;
    for (int label = 0; label < partCount; ++label) keptParts += sizes[size_t(label)] >= std::max(4, largest / 10);
    for (size_t i = 0; i < labels.size(); ++i) {
      const bool keep = labels[i] >= 0 && sizes[size_t(labels[i])] >= std::max(4, largest / 10);
      fill.marked[i] = keep;
      kept += keep;
    }
    if (kept <= bestCells) continue;
    bestCells = kept, bestFloor = int(f), best.parts = keptParts;
    bestGrid = std::move(fill);
  }
  if (bestFloor < 0) {
    throw InputError(subject, "no walkable region found automatically: no position near " + std::string(seeds.front().origin) +
                                  " is enclosed, clear of geometry and " + std::to_string(options.eyeHeight) +
                                  " m above a floor; give --start, --region or --area");
  }
  best.region = regionFromCells(bestGrid, subject);
  best.floorZ = floors[size_t(bestFloor)];
  best.walkableCells = bestCells;
  best.probedCells = prober.probed();
  char reason[320];
  std::snprintf(reason, sizeof reason,
                "automatic walkable region: %.1f m2 in %d part%s on the floor at z = %.2f m, flood fill of %.2f m cells from "
                "%s (%d walkable of %d probed)",
                best.region.area(), best.parts, best.parts == 1 ? "" : "s", best.floorZ, cell, seeds.front().origin,
                best.walkableCells, best.probedCells);
  best.reason = reason;
  return best;
}

}  // namespace triwalk
