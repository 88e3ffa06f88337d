// `triwalk bench --only tiles`: tiled decimation of generated floors of
// growing size, run as a batch scheduler runs it (tiles plan, each tile a
// process of its own, `jobs` at a time, stitch), so that each tile
// process's own peak memory is measured (wait4's ru_maxrss).

#include "app/bench/bench_groups.h"
#include "core/selection/tile_files.h"
#include "core/support/errors.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <map>

namespace triwalk {
namespace {

struct ChildRun {
  double seconds = 0.0;
  double peakGigabytes = 0.0;
};

// Starts this program with arguments, its output to /dev/null.
pid_t startChild(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  std::string self = "/proc/self/exe";
  argv.push_back(self.data());
  std::vector<std::string> copies = arguments;
  for (std::string& a : copies) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    if (std::freopen("/dev/null", "w", stdout) == nullptr) _exit(127);
    execv("/proc/self/exe", argv.data());
    _exit(127);
  }
  if (pid < 0) throw InputError("bench", "could not start a child process");
  return pid;
}

// Waits for one child; its peak resident memory.
std::pair<pid_t, double> waitChild(const std::string& what) {
  int status = 0;
  rusage usage{};
  const pid_t pid = wait4(-1, &status, 0, &usage);
  if (pid < 0) throw InputError("bench", "lost a child process");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) throw InputError("bench", what + " failed");
  return {pid, double(usage.ru_maxrss) / (1024.0 * 1024.0)};
}

ChildRun runChild(const std::vector<std::string>& arguments, const std::string& what) {
  const BenchClock::time_point start = BenchClock::now();
  startChild(arguments);
  const double peak = waitChild(what).second;
  return {secondsSince(start), peak};
}

struct TiledFloor {
  int samples = 0, tiles = 0;
  double captureSeconds = 0.0, planSeconds = 0.0, tilesSeconds = 0.0, stitchSeconds = 0.0;
  double tilePeak = 0.0, stitchPeak = 0.0, planPeak = 0.0;
  ChildRun untiled;  // the same floor decimated whole (the first floor, when asked)
  ChildRun eval;     // Table 1 for the tiled selection (eval reads by tiles above kTileSamples)
  size_t largestTile = 0, references = 0;
  double seconds() const { return planSeconds + tilesSeconds + stitchSeconds; }
};

TiledFloor decimateFloor(const std::string& floor, int width, int jobs, bool alsoWhole) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("triwalk-bench-tiles-" + floor);
  std::filesystem::remove_all(folder);
  struct Cleanup {
    std::filesystem::path folder;
    ~Cleanup() {
      std::error_code ignored;
      std::filesystem::remove_all(folder, ignored);
    }
  } cleanup{folder};
  const std::string data = (folder / "data").string(), work = (folder / "work").string();
  TiledFloor result;
  result.captureSeconds = runChild({"capture", "--quiet", "--scene", "builtin-floor:" + floor, "--width", std::to_string(width),
                                    "--probes", "20", "--out", data},
                                   "capture of builtin-floor:" + floor)
                              .seconds;
  const ChildRun plan = runChild({"tiles", "plan", "--quiet", "--dataset", data, "--out", work, "--jobs", std::to_string(jobs)},
                                 "tiles plan");
  result.planSeconds = plan.seconds;
  result.planPeak = plan.peakGigabytes;
  const Dataset dataset = Dataset::open(data);
  const TilePlan tilePlan = readTilePlan(work, dataset);
  result.samples = dataset.sampleCount();
  result.tiles = int(tilePlan.tiles.size());
  for (const Tile& tile : tilePlan.tiles) result.largestTile = std::max(result.largestTile, tile.samples.size());

  const BenchClock::time_point start = BenchClock::now();
  int next = 0, running = 0;
  while (next < result.tiles || running > 0) {
    while (running < jobs && next < result.tiles) {
      startChild({"tiles", "run", "--quiet", "--plan", work, "--tile", std::to_string(next++)});
      ++running;
    }
    result.tilePeak = std::max(result.tilePeak, waitChild("a tile").second);
    --running;
  }
  result.tilesSeconds = secondsSince(start);
  const ChildRun stitch = runChild({"tiles", "stitch", "--quiet", "--plan", work, "--out", (folder / "selection.json").string()},
                                   "tiles stitch");
  result.stitchSeconds = stitch.seconds;
  result.stitchPeak = stitch.peakGigabytes;
  result.eval = runChild({"eval", "--quiet", "--dataset", data, "--selection", (folder / "selection.json").string()}, "eval");
  result.references = readSelection(folder / "selection.json", dataset).samples.size();
  if (alsoWhole) {
    result.untiled = runChild({"decimate", "--quiet", "--tiles", "off", "--dataset", data, "--out", (folder / "whole.json").string()},
                              "the untiled decimation");
  }
  return result;
}


}  // namespace

void benchTiles(BenchTable& table, const std::vector<std::string>& floors, int width, int jobs, bool againstWhole) {
  std::vector<TiledFloor> runs;
  for (const std::string& floor : floors) {
    const TiledFloor run = decimateFloor(floor, width, jobs, againstWhole && runs.empty());
    const std::string size = std::to_string(run.samples) + " samples " + std::to_string(width) + "x" +
                             std::to_string(width / 2) + " (builtin-floor:" + floor + "), " + std::to_string(run.tiles) +
                             " tiles, " + std::to_string(jobs) + " at a time";
    table.add({"tiled decimation: plan + tiles + stitch", size,
               formatNumber(run.planSeconds, 1) + " + " + formatNumber(run.tilesSeconds, 1) + " + " +
                   formatNumber(run.stitchSeconds, 1) + " = " + formatNumber(run.seconds(), 1) + " s",
               std::to_string(run.references) + " references; capture " + formatNumber(run.captureSeconds, 1) +
                   " s; largest tile " + std::to_string(run.largestTile) + " samples"});
    table.add({"capture, tiled decimation and eval, end to end", size,
               formatNumber(run.captureSeconds + run.seconds() + run.eval.seconds, 1) + " s",
               "eval " + formatNumber(run.eval.seconds, 1) + " s, peak " + formatNumber(run.eval.peakGigabytes, 2) + " GiB"});
    table.add({"tiled decimation: peak memory of one process", size,
               formatNumber(run.tilePeak, 2) + " GiB a tile",
               "plan " + formatNumber(run.planPeak, 2) + " GiB, stitch " + formatNumber(run.stitchPeak, 2) + " GiB"});
    if (run.untiled.seconds > 0.0) {
      table.add({"the same floor decimated whole (--tiles off)", std::to_string(run.samples) + " samples",
                 formatNumber(run.untiled.seconds, 1) + " s", "peak " + formatNumber(run.untiled.peakGigabytes, 2) +
                                                                  " GiB; tiled over untiled: " +
                                                                  formatRatio(run.seconds(), run.untiled.seconds)});
    }
    runs.push_back(run);
  }
  if (runs.size() >= 2) {
    const TiledFloor& small = runs.front();
    const TiledFloor& large = runs.back();
    const std::string sizes = std::to_string(small.samples) + " -> " + std::to_string(large.samples) + " samples";
    table.add({"tiled decimation time as the capture grows", sizes, formatRatio(large.seconds(), small.seconds()),
               "samples " + formatRatio(large.samples, small.samples) + "; issue 69's target <= 4.4x for 4x the samples"});
    table.add({"peak memory of a tile process as the capture grows", sizes, formatRatio(large.tilePeak, small.tilePeak),
               formatNumber(small.tilePeak, 2) + " -> " + formatNumber(large.tilePeak, 2) +
                   " GiB; issue 69's target within 1.2x, <= 4 GiB"});
  }
}

}  // namespace triwalk
