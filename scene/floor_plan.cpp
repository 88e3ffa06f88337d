#include "scene/floor_plan.h"

#include "core/geometry/cell_region.h"
#include "core/support/errors.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <random>
#include <vector>

namespace triwalk {

namespace {

// Metres, between wall centre lines unless said otherwise.
constexpr double kWall = 0.2;            // wall thickness
constexpr double kRoomWidth = 5.0;       // along x
constexpr double kRoomDepth = 4.5;       // along y
constexpr double kCorridorWidth = 2.2;   // the corridors between rows and the spine
constexpr double kCeiling = 3.0;
constexpr double kDoorWidth = 1.2;
constexpr double kDoorTop = 2.1;
constexpr double kClearance = 0.3;       // a sample's distance from walls and cabinets
constexpr double kCell = 0.1;            // the walkable region is traced from cells this size
constexpr int kLargestSide = 64;         // rooms a side
constexpr double kNeighbourDoorChance = 0.35;

struct Rectangle {
  glm::dvec2 lower, upper;
};

enum class BandKind { Room, Corridor };

struct Band {
  BandKind kind;
  int row;  // room row, or -1 for a corridor
  double y0, y1;
};

// Uniform in [low, high) from a 32-bit engine, the same on every platform
// (std::uniform_real_distribution is not).
double uniform(std::mt19937& engine, double low, double high) {
  return low + (high - low) * double(engine() >> 8) * (1.0 / 16777216.0);
}

nlohmann::json vec2(glm::dvec2 v) { return nlohmann::json::array({v.x, v.y}); }
nlohmann::json vec3(glm::dvec2 v, double z) { return nlohmann::json::array({v.x, v.y, z}); }

nlohmann::json box(const std::string& material, glm::dvec2 lower, double bottom, glm::dvec2 upper, double top) {
  return {{"type", "box"}, {"material", material}, {"min", vec3(lower, bottom)}, {"max", vec3(upper, top)}, {"cell_size", 0.3}};
}

struct Opening {
  double start, end, top;  // along the wall from its `from` end
};

nlohmann::json wall(glm::dvec2 from, glm::dvec2 to, const std::vector<Opening>& openings) {
  nlohmann::json object = {{"type", "wall"}, {"material", "hall_wall"}, {"from", vec2(from)}, {"to", vec2(to)},
                           {"top", kCeiling}, {"thickness", kWall}, {"cell_size", 1.5}};
  nlohmann::json list = nlohmann::json::array();
  for (const Opening& opening : openings) list.push_back({{"start", opening.start}, {"end", opening.end}, {"top", opening.top}});
  if (!list.empty()) object["openings"] = list;
  return object;
}

// The cells whose centres lie in a rectangle, set to `value`.
void markCells(CellGrid& grid, const Rectangle& area, bool value) {
  const int x0 = std::max(0, int(std::ceil((area.lower.x - grid.origin.x) / grid.cellSize - 0.5 - 1e-9)));
  const int x1 = std::min(grid.columns - 1, int(std::floor((area.upper.x - grid.origin.x) / grid.cellSize - 0.5 + 1e-9)));
  const int y0 = std::max(0, int(std::ceil((area.lower.y - grid.origin.y) / grid.cellSize - 0.5 - 1e-9)));
  const int y1 = std::min(grid.rows - 1, int(std::floor((area.upper.y - grid.origin.y) / grid.cellSize - 0.5 + 1e-9)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) grid.set(x, y, value);
  }
}

// A band's or room's floor between its walls, less the clearance.
Rectangle clearInterior(glm::dvec2 lower, glm::dvec2 upper) {
  const double inset = 0.5 * kWall + kClearance;
  return {lower + inset, upper - inset};
}

class FloorPlanBuilder {
public:
  FloorPlanBuilder(const FloorPlanSize& size, const nlohmann::json& builtin) : size_(size), engine_(size.seed) {
    description_ = {{"name", "builtin-floor-" + std::to_string(size.columns) + "x" + std::to_string(size.rows)},
                    {"comment", "A procedural floor of rooms, corridors and doors (scene/floor_plan.h)."},
                    {"ambient", builtin.at("ambient")},
                    {"sky", builtin.at("sky")},
                    {"materials", builtin.at("materials")},
                    {"lights", nlohmann::json::array()},
                    {"objects", nlohmann::json::array()}};
    layBands();
    width_ = kCorridorWidth + size.columns * kRoomWidth;
    depth_ = bands_.back().y1;
    grid_ = CellGrid(glm::dvec2(0.0), kCell, int(std::lround(width_ / kCell)), int(std::lround(depth_ / kCell)));
  }

  FloorPlan build() {
    addShell();
    addRooms();
    addCorridors();
    description_["walkable_area"] = {{"min", vec2(glm::dvec2(0.0))}, {"max", vec2({width_, depth_})},
                                     {"eye_height", 1.6}, {"floor_height", 0.0}};
    removeCornerContacts(grid_);
    FloorPlan plan;
    plan.region = regionFromCells(grid_, description_["name"].get<std::string>());
    plan.description = std::move(description_);
    plan.sampleSpacing = 1.0f / 3.0f;
    return plan;
  }

private:
  // Room rows from south to north; a corridor after every even row, so
  // rows 2k and 2k+1 face the corridor between them.
  void layBands() {
    double y = 0.0;
    for (int row = 0; row < size_.rows; ++row) {
      bands_.push_back({BandKind::Room, row, y, y + kRoomDepth});
      y += kRoomDepth;
      if (row % 2 == 0) {
        bands_.push_back({BandKind::Corridor, -1, y, y + kCorridorWidth});
        y += kCorridorWidth;
      }
    }
  }

  nlohmann::json& objects() { return description_["objects"]; }

  void addLight(glm::dvec2 at, double strength, double range) {
    description_["lights"].push_back({{"position", vec3(at, kCeiling - 0.2)},
                                      {"color", {0.55 * strength, 0.50 * strength, 0.42 * strength}},
                                      {"range", range}});
  }

  // Floor, ceiling, the outer walls and the spine corridor on the west.
  void addShell() {
    objects().push_back({{"type", "floor"}, {"material", "room_floor"}, {"min", vec2(glm::dvec2(0.0))},
                         {"max", vec2({width_, depth_})}, {"z", 0.0}, {"cell_size", 2.0}});
    objects().push_back({{"type", "ceiling"}, {"material", "hall_ceiling"}, {"min", vec2(glm::dvec2(0.0))},
                         {"max", vec2({width_, depth_})}, {"z", kCeiling}, {"cell_size", 2.0}});
    objects().push_back(wall({0.0, 0.0}, {width_, 0.0}, {}));
    objects().push_back(wall({0.0, depth_}, {width_, depth_}, {}));
    objects().push_back(wall({0.0, 0.0}, {0.0, depth_}, {}));
    objects().push_back(wall({width_, 0.0}, {width_, depth_}, {}));
    // The spine's east wall, open where each corridor meets it.
    std::vector<Opening> corridorMouths;
    for (const Band& band : bands_) {
      if (band.kind != BandKind::Corridor) continue;
      corridorMouths.push_back({band.y0 + 0.5 * kWall, band.y1 - 0.5 * kWall, kCeiling});
      markCells(grid_, {{kCorridorWidth - 0.5 * kWall - kClearance, band.y0 + 0.5 * kWall + kClearance},
                        {kCorridorWidth + 0.5 * kWall + kClearance, band.y1 - 0.5 * kWall - kClearance}},
                true);
    }
    objects().push_back(wall({kCorridorWidth, 0.0}, {kCorridorWidth, depth_}, corridorMouths));
    markCells(grid_, clearInterior({0.0, 0.0}, {kCorridorWidth, depth_}), true);
    for (double y = 2.5; y < depth_; y += 5.0) addLight({0.5 * kCorridorWidth, y}, 0.8, 3.5);
  }

  void addCorridors() {
    for (const Band& band : bands_) {
      if (band.kind != BandKind::Corridor) continue;
      markCells(grid_, clearInterior({kCorridorWidth, band.y0}, {width_, band.y1}), true);
      for (double x = kCorridorWidth + 2.5; x < width_; x += 5.0) addLight({x, 0.5 * (band.y0 + band.y1)}, 0.8, 3.5);
    }
  }

  void addRooms() {
    for (const Band& band : bands_) {
      if (band.kind != BandKind::Room) continue;
      // Even rows open north onto their corridor, odd rows south.
      const bool doorNorth = band.row % 2 == 0;
      const double doorLine = doorNorth ? band.y1 : band.y0;
      std::vector<Opening> doors;
      for (int column = 0; column < size_.columns; ++column) {
        const double x0 = kCorridorWidth + column * kRoomWidth, x1 = x0 + kRoomWidth;
        const double start = x0 + uniform(engine_, 0.6, kRoomWidth - 0.6 - kDoorWidth);
        doors.push_back({start - kCorridorWidth, start + kDoorWidth - kCorridorWidth, kDoorTop});
        markCells(grid_, {{start + kClearance, doorLine - 0.5 * kWall - kClearance},
                          {start + kDoorWidth - kClearance, doorLine + 0.5 * kWall + kClearance}},
                  true);
        addRoom(column, {x0, band.y0}, {x1, band.y1}, doorNorth);
      }
      objects().push_back(wall({kCorridorWidth, doorLine}, {width_, doorLine}, doors));
      // The line on the room's other side: a corridor's, or the next row's.
      const double backLine = doorNorth ? band.y0 : band.y1;
      // Odd rows add the wall they share with the even row north of them;
      // the outer walls are the shell's.
      const bool outer = backLine == 0.0 || backLine == depth_;
      if (!outer && !doorNorth) objects().push_back(wall({kCorridorWidth, backLine}, {width_, backLine}, {}));
    }
  }

  void addRoom(int column, glm::dvec2 lower, glm::dvec2 upper, bool doorNorth) {
    markCells(grid_, clearInterior(lower, upper), true);
    addLight(0.5 * (lower + upper), 1.0, 3.0);
    // The wall to the east neighbour, with a door now and then.
    if (column + 1 < size_.columns) {
      std::vector<Opening> door;
      if (uniform(engine_, 0.0, 1.0) < kNeighbourDoorChance) {
        const double start = uniform(engine_, 0.6, kRoomDepth - 0.6 - kDoorWidth);
        door.push_back({start, start + kDoorWidth, kDoorTop});
        markCells(grid_, {{upper.x - 0.5 * kWall - kClearance, lower.y + start + kClearance},
                          {upper.x + 0.5 * kWall + kClearance, lower.y + start + kDoorWidth - kClearance}},
                  true);
      }
      objects().push_back(wall({upper.x, lower.y}, {upper.x, upper.y}, door));
    }
    const Rectangle inside = {lower + 0.5 * kWall, upper - 0.5 * kWall};
    // A cabinet against the wall without the corridor door; the region keeps clear of it.
    const double cabinetWidth = uniform(engine_, 1.2, 2.0), cabinetDepth = 0.45;
    const double cabinetX = uniform(engine_, inside.lower.x + 0.2, inside.upper.x - 0.2 - cabinetWidth);
    const double wallY = doorNorth ? inside.lower.y : inside.upper.y - cabinetDepth;
    const Rectangle cabinet = {{cabinetX, wallY}, {cabinetX + cabinetWidth, wallY + cabinetDepth}};
    objects().push_back(box("bookshelf", cabinet.lower, 0.0, cabinet.upper, 2.0));
    markCells(grid_, {cabinet.lower - kClearance, cabinet.upper + kClearance}, false);
    // A table and crates below eye height: a walker sees over them.
    const glm::dvec2 tableSize(1.4, 0.8);
    const glm::dvec2 tableLower(uniform(engine_, inside.lower.x + 0.8, inside.upper.x - 0.8 - tableSize.x),
                                uniform(engine_, inside.lower.y + 1.0, inside.upper.y - 1.0 - tableSize.y));
    objects().push_back(box("table", tableLower, 0.72, tableLower + tableSize, 0.78));
    for (const glm::dvec2 corner : {glm::dvec2(0.05, 0.05), glm::dvec2(tableSize.x - 0.11, 0.05),
                                    glm::dvec2(0.05, tableSize.y - 0.11), glm::dvec2(tableSize.x - 0.11, tableSize.y - 0.11)}) {
      objects().push_back(box("table", tableLower + corner, 0.0, tableLower + corner + 0.06, 0.72));
    }
    // Crates stand clear of the table (tries, then none): one poking through its top looks broken.
    const int crates = 1 + int(engine_() % 2);
    for (int i = 0; i < crates; ++i) {
      const double side = uniform(engine_, 0.45, 0.8);
      for (int attempt = 0; attempt < 20; ++attempt) {
        const glm::dvec2 at(uniform(engine_, inside.lower.x + 0.5, inside.upper.x - 0.5 - side),
                            uniform(engine_, inside.lower.y + 0.5, inside.upper.y - 0.5 - side));
        const bool clear = at.x > tableLower.x + tableSize.x + 0.1 || at.x + side < tableLower.x - 0.1 ||
                           at.y > tableLower.y + tableSize.y + 0.1 || at.y + side < tableLower.y - 0.1;
        if (!clear) continue;
        objects().push_back(box("crate", at, 0.0, at + side, side));
        break;
      }
    }
  }

  FloorPlanSize size_;
  std::mt19937 engine_;
  nlohmann::json description_;
  std::vector<Band> bands_;
  double width_ = 0.0, depth_ = 0.0;
  CellGrid grid_;
};

}  // namespace

std::optional<FloorPlanSize> parseFloorPlanSpec(const std::string& spec) {
  const std::string prefix = "builtin-floor";
  if (!spec.starts_with(prefix)) return std::nullopt;
  FloorPlanSize size;
  const std::string rest = spec.substr(prefix.size());
  const char* first = rest.data();
  const char* last = rest.data() + rest.size();
  auto number = [&](auto& value) {
    const auto [end, error] = std::from_chars(first, last, value);
    const bool read = error == std::errc() && end != first;
    first = end;
    return read;
  };
  const bool parsed = first != last && *first++ == ':' && number(size.columns) && first != last && *first++ == 'x' &&
                      number(size.rows) && (first == last || (*first++ == ':' && number(size.seed) && first == last));
  if (!parsed || size.columns < 1 || size.rows < 1 || size.columns > kLargestSide || size.rows > kLargestSide) {
    throw InputError("--scene", "'" + spec + "': a floor is builtin-floor:CxR[:SEED], C and R rooms from 1 to " +
                                    std::to_string(kLargestSide) + " (e.g. builtin-floor:8x5)");
  }
  return size;
}

FloorPlan makeFloorPlan(const FloorPlanSize& size, const nlohmann::json& builtinDescription) {
  return FloorPlanBuilder(size, builtinDescription).build();
}

}  // namespace triwalk
