#pragma once
// The files of a tiled selection's work folder: plan.json, what every
// tile runs with, and tile_K.json, what tile K chose. Each is written
// atomically, so a tile killed mid-way leaves no file and is simply run
// again; a tile's file names the plan it was made for (a hash of
// plan.json), so a stale one is never stitched.
//
// plan.json: {"format": "triwalk-tile-plan", "version": 1,
//   "dataset": {"directory": "/abs/path", "samples": 28807},
//   "settings": {...}  (a selection file's, thresholds resolved),
//   "dense_mean_error": 1.21, "margin": 1.9, "band": 0.95, "target": 0,
//   "tiles": [{"core": [x0, y0, x1, y1], "members": [ids], "samples": [ids], "target": 0}, ...]}
// tile_0003.json: {"format": "triwalk-tile", "version": 1, "plan": "hex hash",
//   "tile": 3, "references": [ids], "collapses": 812, "moves": 40, "seconds": 95.1}

#include "core/io/dataset.h"
#include "core/selection/tiled_selection.h"

#include <filesystem>
#include <optional>
#include <string>

namespace triwalk {

// Writes folder/plan.json atomically (creating folder).
void writeTilePlan(const std::filesystem::path& folder, const TilePlan& plan, const Dataset& dataset);

// The data set folder a plan names (InputError naming plan.json if the
// folder holds none, or a bad one).
std::filesystem::path tilePlanDataset(const std::filesystem::path& folder);

// Reads and validates folder/plan.json against its data set.
TilePlan readTilePlan(const std::filesystem::path& folder, const Dataset& dataset);

std::filesystem::path tileOutcomeFile(const std::filesystem::path& folder, int tile);

// Writes tile_K.json atomically, naming the plan (read from folder).
void writeTileOutcome(const std::filesystem::path& folder, const TilePlan& plan, int tile, const TileOutcome& outcome,
                      const Dataset& dataset);

// Tile K's outcome if its file exists and was made for the plan (read from folder)
// (a file made for another plan counts as missing); InputError naming a
// corrupt one.
std::optional<TileOutcome> readTileOutcome(const std::filesystem::path& folder, int tile, const TilePlan& plan,
                                           const Dataset& dataset);

// Every tile's outcome, in order; InputError in one line naming the first
// missing tile and how to run it.
std::vector<TileOutcome> readTileOutcomes(const std::filesystem::path& folder, const TilePlan& plan,
                                          const Dataset& dataset);

}  // namespace triwalk
