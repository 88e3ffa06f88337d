#include "app/setup/tile_jobs.h"

#include "app/setup/mpi_world.h"
#include "core/io/output_lock.h"
#include "core/selection/tile_files.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

namespace triwalk {
namespace {

// The tiles of the plan with no outcome for it in folder.
std::vector<int> tilesToRun(const std::filesystem::path& folder, const Dataset& dataset, const TilePlan& plan) {
  std::vector<int> pending;
  for (int k = 0; k < int(plan.tiles.size()); ++k) {
    if (!readTileOutcome(folder, k, plan, dataset)) pending.push_back(k);
  }
  return pending;
}

// The plan in folder if it was made for this request, else a new one.
TilePlan planOrResume(const Dataset& dataset, const TilePlanRequest& request, const std::filesystem::path& folder,
                      bool quiet) {
  if (std::filesystem::exists(folder / "plan.json")) {
    try {
      TilePlan found = readTilePlan(folder, dataset);
      if (found.request == nlohmann::json{{"settings", request.settings}, {"tiles", request.tiles}} &&
          found.datasetDirectory == std::filesystem::absolute(dataset.directory()).lexically_normal().string()) {
        if (!quiet) std::printf("going on with the tiles of %s\n", folder.c_str());
        return found;
      }
    } catch (const InputError&) {
      // A plan of another data set or a damaged one: planned again below.
    }
  }
  writeTilePlan(folder, planTiles(dataset, request, quiet), dataset);
  return readTilePlan(folder, dataset);
}

// The tiles not yet taken, shared by rank 0's own worker thread and the
// tiles it hands to the other ranks.
class TileQueue {
public:
  explicit TileQueue(std::vector<int> pending) : pending_(std::move(pending)) {}
  std::optional<int> take() {
    const std::lock_guard lock(mutex_);
    if (next_ >= pending_.size() || !failed_.empty()) return std::nullopt;
    return pending_[next_++];
  }
  void fail(int tile, int rank) {
    const std::lock_guard lock(mutex_);
    failed_.emplace_back(tile, rank);
  }
  std::optional<std::pair<int, int>> firstFailure() {
    const std::lock_guard lock(mutex_);
    if (failed_.empty()) return std::nullopt;
    return failed_.front();
  }

private:
  std::mutex mutex_;
  std::vector<int> pending_;
  size_t next_ = 0;
  std::vector<std::pair<int, int>> failed_;  // tile, rank
};

// Rank 0 of an MPI run: runs tiles itself on a thread of its own while its
// main thread (the only one that talks to MPI) hands each other rank a tile
// as it asks for one, until none is left or one failed. Messages: {tile
// finished or -1, 1 if it failed}.
void handOutTiles(const MpiWorld& world, const std::filesystem::path& folder, const Dataset& dataset,
                  const TilePlan& plan, const std::vector<int>& pending, bool quiet) {
  ProgressReporter progress("tiles, over " + std::to_string(world.size()) + " MPI ranks", pending.size(), quiet);
  TileQueue queue(pending);
  const size_t layerCacheBytes = tileLayerCacheBytes(world.localSize());
  std::thread local([&] {
    while (const std::optional<int> tile = queue.take()) {
      try {
        writeTileOutcome(folder, plan, *tile, runTile(dataset, plan, *tile, layerCacheBytes, true), dataset);
        progress.advance();
      } catch (const std::exception& error) {
        std::fprintf(stderr, "triwalk: MPI rank 0, tile %d: %s\n", *tile, error.what());
        queue.fail(*tile, 0);
      }
    }
  });
  int working = world.size() - 1;
  while (working > 0) {
    std::array<int, 2> message{};
    const int rank = world.receive(message);
    if (message[1] != 0) {
      queue.fail(message[0], rank);
    } else if (message[0] >= 0) {
      progress.advance();
    }
    if (const std::optional<int> tile = queue.take()) {
      world.send(rank, {*tile, 0});
    } else {
      world.send(rank, {-1, 0});
      --working;
    }
  }
  local.join();
  progress.finish();
  throwIfInterrupted();
  if (const auto failure = queue.firstFailure()) {
    const auto [tile, rank] = *failure;
    throw InputError(tileOutcomeFile(folder, tile).string(),
                     "tile " + std::to_string(tile) + " failed on MPI rank " + std::to_string(rank) +
                         " (its message is above); run the same command again to rerun the tiles not finished");
  }
}

void runHandedTiles(const MpiWorld& world, const std::filesystem::path& folder, const Dataset& dataset,
                    const TilePlan& plan) {
  const size_t layerCacheBytes = tileLayerCacheBytes(world.localSize());
  std::array<int, 2> report{-1, 0};
  while (true) {
    world.send(0, report);
    const int tile = world.receiveFrom(0)[0];
    if (tile < 0) return;
    try {
      writeTileOutcome(folder, plan, tile, runTile(dataset, plan, tile, layerCacheBytes, true), dataset);
      report = {tile, 0};
    } catch (const std::exception& error) {
      std::fprintf(stderr, "triwalk: MPI rank %d, tile %d: %s\n", world.rank(), tile, error.what());
      report = {tile, 1};
    }
  }
}

}  // namespace

std::optional<int> parseTileCount(const std::string& value) {
  int count = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), count);
  if (error != std::errc() || end != value.data() + value.size() || count < 1 || count > 100000) return std::nullopt;
  return count;
}

int tileCountFor(const std::string& tiles, int samples) {
  if (tiles == "off") return 1;
  if (tiles == "auto") return size_t(samples) > kTileSamples ? 0 : 1;
  const std::optional<int> count = parseTileCount(tiles);
  if (!count) throw InputError("--tiles", "must be auto, off or a number of tiles, got '" + tiles + "'");
  return *count;
}

int defaultJobs() { return std::max(1, tbb::this_task_arena::max_concurrency()); }

void runTilesHere(const std::filesystem::path& folder, const Dataset& dataset, const TilePlan& plan, int jobs,
                  bool quiet) {
  const std::vector<int> pending = tilesToRun(folder, dataset, plan);
  if (!quiet && pending.size() < plan.tiles.size()) {
    std::printf("%zu of %zu tiles already run for this plan\n", plan.tiles.size() - pending.size(), plan.tiles.size());
  }
  const int concurrent = std::max(1, std::min(jobs, int(pending.size())));
  const size_t layerCacheBytes = tileLayerCacheBytes(concurrent);
  ProgressReporter progress("tiles, " + std::to_string(concurrent) + " at a time", pending.size(), quiet);
  // One tile per job; each tile's errors use the threads its job is given.
  tbb::task_arena arena(concurrent);
  arena.execute([&] {
    tbb::parallel_for(size_t(0), pending.size(), size_t(1), [&](size_t i) {
      if (interruptRequested()) return;
      writeTileOutcome(folder, plan, pending[i], runTile(dataset, plan, pending[i], layerCacheBytes, true), dataset);
      progress.advance();
    });
  });
  progress.finish();
  throwIfInterrupted();
}

std::optional<StitchResult> decimateInTiles(const Dataset& dataset, const TilePlanRequest& request,
                                            const std::filesystem::path& folder, bool quiet) {
  if (!startedByMpirun()) {
    const OutputLock lock(folder);
    const TilePlan plan = planOrResume(dataset, request, folder, quiet);
    runTilesHere(folder, dataset, plan, request.jobs, quiet);
    return stitchTiles(dataset, plan, readTileOutcomes(folder, plan, dataset), request.jobs, quiet);
  }
  const MpiWorld world;
  if (world.rank() != 0) {
    if (world.broadcast(0) != 0) return std::nullopt;  // rank 0 could not plan, and says why
    const TilePlan plan = readTilePlan(folder, dataset);
    runHandedTiles(world, folder, dataset, plan);
    return std::nullopt;
  }
  std::optional<OutputLock> lock;
  std::optional<TilePlan> plan;
  try {
    lock.emplace(folder);
    plan = planOrResume(dataset, request, folder, quiet);
  } catch (...) {
    world.broadcast(1);
    throw;
  }
  world.broadcast(0);
  const std::vector<int> pending = tilesToRun(folder, dataset, *plan);
  handOutTiles(world, folder, dataset, *plan, pending, quiet);
  return stitchTiles(dataset, *plan, readTileOutcomes(folder, *plan, dataset), request.jobs, quiet);
}

}  // namespace triwalk
