#pragma once
// Running the tiles of a tiled selection (core/selection/tiled_selection.h)
// and the whole of it as decimate does: on one machine, `jobs` tiles at a
// time in this process; under mpirun, rank 0 plans, hands tiles out as
// ranks free up and stitches. A tile's outcome is written to the work
// folder as it finishes, so a run stopped or killed goes on where it was.

#include "core/io/dataset.h"
#include "core/selection/tiled_selection.h"

#include <filesystem>
#include <optional>
#include <string>

namespace triwalk {

// --tiles: a count from 1 to 100000, or nothing.
std::optional<int> parseTileCount(const std::string& value);
// The tiles for --tiles auto|off|N on a data set, as TilePlanRequest::tiles
// counts them: 1 untiled (off, or auto up to kTileSamples samples), 0 as
// many as keep each tile within kTileSamples (auto above it), or N.
int tileCountFor(const std::string& tiles, int samples);
// --jobs by default: this machine's cores.
int defaultJobs();

// Runs the tiles of the plan in folder that have no outcome for it yet,
// `jobs` at a time; progress unless quiet.
void runTilesHere(const std::filesystem::path& folder, const Dataset& dataset, const TilePlan& plan, int jobs,
                  bool quiet);

// Plans in folder (or finds a plan made for the same request there), runs
// the tiles not yet run, and stitches; under mpirun, across the ranks (the
// other ranks return nothing). Holds folder's lock throughout.
std::optional<StitchResult> decimateInTiles(const Dataset& dataset, const TilePlanRequest& request,
                                            const std::filesystem::path& folder, bool quiet);

}  // namespace triwalk
