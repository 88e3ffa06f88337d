#include "core/selection/tile_files.h"

#include "core/io/atomic_file.h"
#include "core/io/json_fields.h"
#include "core/support/errors.h"
#include "core/support/input_limits.h"
#include "core/support/stable_hash.h"

#include <cinttypes>
#include <cstdio>
#include <unordered_map>

namespace triwalk {
namespace {

constexpr int kTilePlanVersion = 1;
constexpr const char* kPlanFileName = "plan.json";

nlohmann::json idsOf(std::span<const int> indices, const Dataset& dataset) {
  nlohmann::json ids = nlohmann::json::array();
  for (int i : indices) ids.push_back(dataset.sample(i).id);
  return ids;
}

// Sample ids back to sorted indices, each known to the data set.
class IdReader {
public:
  explicit IdReader(const Dataset& dataset) {
    for (int i = 0; i < dataset.sampleCount(); ++i) index_[dataset.sample(i).id] = i;
  }
  std::vector<int> indices(const JsonObject& object, const std::string& key) const {
    const nlohmann::json& ids = object.array(key);
    std::vector<int> result;
    result.reserve(ids.size());
    for (size_t i = 0; i < ids.size(); ++i) {
      const std::string where = object.where(key) + "[" + std::to_string(i) + "]";
      const auto found = index_.find(jsonInteger(ids[i], object.file(), where));
      if (found == index_.end()) throw InputError(object.file(), where + ": not a sample id of the data set");
      result.push_back(found->second);
    }
    std::sort(result.begin(), result.end());
    if (std::adjacent_find(result.begin(), result.end()) != result.end()) object.fail(key + " repeats a sample");
    return result;
  }

private:
  std::unordered_map<int, int> index_;
};

std::string planKey(const std::filesystem::path& folder) {
  const std::string text = readTextFile(folder / kPlanFileName);
  StableHash hash;
  hash.addBytes(std::as_bytes(std::span<const char>(text.data(), text.size())));
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, hash.value());
  return hex;
}

}  // namespace

void writeTilePlan(const std::filesystem::path& folder, const TilePlan& plan, const Dataset& dataset) {
  nlohmann::json tiles = nlohmann::json::array();
  for (size_t k = 0; k < plan.tiles.size(); ++k) {
    const Tile& tile = plan.tiles[k];
    tiles.push_back({{"core", {tile.core.lower.x, tile.core.lower.y, tile.core.upper.x, tile.core.upper.y}},
                     {"members", idsOf(tile.core.members, dataset)},
                     {"samples", idsOf(tile.samples, dataset)},
                     {"target", plan.target > 0 ? plan.tileTargets[k] : 0}});
  }
  const nlohmann::json document = {{"format", "triwalk-tile-plan"},
                                   {"version", kTilePlanVersion},
                                   {"request", plan.request},
                                   {"dataset", {{"directory", plan.datasetDirectory}, {"samples", plan.datasetSamples}}},
                                   {"settings", plan.settings},
                                   {"dense_mean_error", plan.denseMeanError},
                                   {"margin", plan.margin},
                                   {"band", plan.band},
                                   {"target", plan.target},
                                   {"tiles", tiles}};
  std::filesystem::create_directories(folder);
  writeJsonFile(folder / kPlanFileName, document);
}

namespace {

JsonObject planRoot(const nlohmann::json& document, const std::filesystem::path& file) {
  const JsonObject root(document, file.string());
  if (root.stringOr("format", "") != "triwalk-tile-plan") root.fail("not a triwalk tile plan (format field)");
  if (root.integer("version") != kTilePlanVersion) root.fail("unknown tile plan version");
  return root;
}

}  // namespace

std::filesystem::path tilePlanDataset(const std::filesystem::path& folder) {
  const std::filesystem::path file = folder / kPlanFileName;
  const nlohmann::json document = readJsonFile(file);
  return planRoot(document, file).object("dataset").string("directory");
}

TilePlan readTilePlan(const std::filesystem::path& folder, const Dataset& dataset) {
  const std::filesystem::path file = folder / kPlanFileName;
  const nlohmann::json document = readJsonFile(file);
  const JsonObject root = planRoot(document, file);
  TilePlan plan;
  plan.key = planKey(folder);
  const JsonObject source = root.object("dataset");
  plan.datasetDirectory = source.string("directory");
  plan.datasetSamples = source.integer("samples");
  if (plan.datasetSamples != dataset.sampleCount()) {
    source.fail("the plan was made for " + std::to_string(plan.datasetSamples) + " samples, the data set has " +
                std::to_string(dataset.sampleCount()));
  }
  plan.request = root.object("request").json();
  plan.settings = root.object("settings").json();
  plan.denseMeanError = root.number("dense_mean_error");
  plan.margin = root.number("margin");
  plan.band = root.number("band");
  plan.target = root.integer("target");
  if (!(plan.margin >= 0.0 && plan.band >= 0.0 && plan.denseMeanError >= 0.0) || plan.target < 0) {
    root.fail("margin, band, dense_mean_error and target must not be negative");
  }
  const IdReader ids(dataset);
  const nlohmann::json& tiles = root.array("tiles");
  if (tiles.empty()) root.fail("a plan needs at least one tile");
  std::vector<char> owned(size_t(dataset.sampleCount()), 0);
  for (size_t k = 0; k < tiles.size(); ++k) {
    const JsonObject entry = root.element("tiles", k);
    Tile tile;
    const nlohmann::json& core = entry.array("core");
    if (core.size() != 4 || !std::all_of(core.begin(), core.end(), [](const nlohmann::json& v) {
          return v.is_number() && withinCoordinateBound(v.get<double>());
        })) {
      entry.fail("core must be four coordinates x0, y0, x1, y1 within 100 km");
    }
    tile.core.lower = {core[0].get<double>(), core[1].get<double>()};
    tile.core.upper = {core[2].get<double>(), core[3].get<double>()};
    tile.core.members = ids.indices(entry, "members");
    tile.samples = ids.indices(entry, "samples");
    // Fewer could not be triangulated: said here, naming the plan, not by
    // the tile's run after it has read its views.
    if (tile.samples.size() < 3) {
      entry.fail("samples: a tile needs at least 3, got " + std::to_string(tile.samples.size()));
    }
    for (int m : tile.core.members) {
      if (owned[size_t(m)]) entry.fail("members: sample id " + std::to_string(dataset.sample(m).id) + " is in two cores");
      owned[size_t(m)] = 1;
      if (!std::binary_search(tile.samples.begin(), tile.samples.end(), m)) entry.fail("a member is not among samples");
    }
    const int target = entry.integer("target");
    if (target < 0) entry.fail("target must not be negative, got " + std::to_string(target));
    plan.tileTargets.push_back(target);
    plan.tiles.push_back(std::move(tile));
  }
  if (std::count(owned.begin(), owned.end(), 0) > 0) root.fail("tiles: some samples are in no core");
  return plan;
}

std::filesystem::path tileOutcomeFile(const std::filesystem::path& folder, int tile) {
  char name[32];
  std::snprintf(name, sizeof name, "tile_%04d.json", tile);
  return folder / name;
}

void writeTileOutcome(const std::filesystem::path& folder, const TilePlan& plan, int tile, const TileOutcome& outcome,
                      const Dataset& dataset) {
  TRIWALK_CHECK(!plan.key.empty(), "a tile's outcome names a plan read from its folder");
  const nlohmann::json document = {{"format", "triwalk-tile"},     {"version", kTilePlanVersion},
                                   {"plan", plan.key},       {"tile", tile},
                                   {"references", idsOf(outcome.references, dataset)},
                                   {"collapses", outcome.collapses}, {"moves", outcome.moves},
                                   {"seconds", outcome.seconds}};
  writeJsonFile(tileOutcomeFile(folder, tile), document);
}

std::optional<TileOutcome> readTileOutcome(const std::filesystem::path& folder, int tile, const TilePlan& plan,
                                           const Dataset& dataset) {
  const std::filesystem::path file = tileOutcomeFile(folder, tile);
  if (!std::filesystem::exists(file)) return std::nullopt;
  const nlohmann::json document = readJsonFile(file);
  const JsonObject root(document, file.string());
  if (root.stringOr("format", "") != "triwalk-tile") root.fail("not a triwalk tile (format field)");
  if (root.string("plan") != plan.key) return std::nullopt;
  if (root.integer("tile") != tile) root.fail("holds tile " + std::to_string(root.integer("tile")));
  TileOutcome outcome;
  outcome.references = IdReader(dataset).indices(root, "references");
  const std::vector<int>& members = plan.tiles[size_t(tile)].core.members;
  for (int r : outcome.references) {
    if (!std::binary_search(members.begin(), members.end(), r)) root.fail("references: a sample outside the tile's core");
  }
  const int collapses = root.integer("collapses"), moves = root.integer("moves");
  outcome.seconds = root.number("seconds");
  if (collapses < 0 || moves < 0 || !(outcome.seconds >= 0.0)) root.fail("collapses, moves and seconds must not be negative");
  outcome.collapses = size_t(collapses);
  outcome.moves = size_t(moves);
  return outcome;
}

std::vector<TileOutcome> readTileOutcomes(const std::filesystem::path& folder, const TilePlan& plan,
                                          const Dataset& dataset) {
  std::vector<TileOutcome> outcomes;
  for (int k = 0; k < int(plan.tiles.size()); ++k) {
    std::optional<TileOutcome> outcome = readTileOutcome(folder, k, plan, dataset);
    if (!outcome) {
      throw InputError(tileOutcomeFile(folder, k).string(),
                       "tile " + std::to_string(k) + " of " + std::to_string(plan.tiles.size()) +
                           " has not run for this plan (run: triwalk tiles run --plan " + folder.string() +
                           " --tile " + std::to_string(k) + ")");
    }
    outcomes.push_back(std::move(*outcome));
  }
  return outcomes;
}

}  // namespace triwalk
