#include "app/bench/bench_groups.h"
#include "app/bench/temporary_capture.h"
#include "core/selection/reference_selection.h"

#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

namespace triwalk {

namespace {

// The kernel's high-water mark of resident memory (VmHWM), reset so that
// each decimation of one bench run reports its own peak; false when it
// cannot be reset (the peak then includes what ran before).
bool resetPeakResident() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return bool(clear);
}

double peakResidentGigabytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return double(std::stoull(line.substr(6))) / (1024.0 * 1024.0);  // kB
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / (1024.0 * 1024.0);  // ru_maxrss is in KiB on Linux
}

rusage processUsage() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage;
}

double seconds(const timeval& time) {
  return double(time.tv_sec) + 1e-6 * double(time.tv_usec);
}

}  // namespace

std::string BenchSelectionErrors::describe() const { return describeErrorPanorama(width, stride); }

BenchDecimation runBenchDecimation(const Dataset& dataset, const BenchSelectionErrors& errorChoice) {
  BenchDecimation result;
  result.peakIsOwn = resetPeakResident();
  TriangleErrorSettings settings = selectionErrorDefaults(dataset);  // as decimate prices collapses
  settings.width = errorChoice.width;
  settings.stride = errorChoice.stride;
  const auto loadStart = BenchClock::now();
  // Progress on stderr (minutes of work); the table goes to stdout.
  constexpr bool kQuiet = false;
  DatasetTriangleErrors errors(dataset, settings, LoadedViews::Samples, kQuiet);
  result.loadSeconds = secondsSince(loadStart);
  // What `decimate --max-error 1.85` (the main job) runs: the default
  // cost, boundary and area weights, then the refinement.
  result.settings.decimation.maxError = kPaperMaxError;
  const rusage before = processUsage();
  result.run = selectReferences(dataset, errors, result.settings, kQuiet);
  const rusage after = processUsage();
  result.pageFaults = uint64_t(after.ru_minflt - before.ru_minflt) + uint64_t(after.ru_majflt - before.ru_majflt);
  result.systemSeconds = seconds(after.ru_stime) - seconds(before.ru_stime);
  result.peakGigabytes = peakResidentGigabytes();
  result.layersComputed = errors.layerCache().misses();
  result.layersReused = errors.layerCache().hits();
  result.layersWarpedAgain = errors.layerCache().missesAfterEviction();
  result.layerBudgetGigabytes = double(errors.layerCache().budgetBytes()) / double(1u << 30);
  return result;
}

void benchDecimate(BenchTable& table, const Scene& scene, const std::string& datasetDirectory,
                   const BenchSelectionErrors& errors) {
  std::optional<TemporaryCapture> capture;
  std::filesystem::path directory = datasetDirectory;
  if (directory.empty()) {
    CaptureOptions options;  // the default capture: 30 paths x 15 samples at 1024x512
    options.probes = 0;
    capture.emplace(scene, options, "triwalk-bench-dataset");
    directory = capture->directory();
  }
  const Dataset dataset = Dataset::open(directory);
  const std::string size = std::to_string(dataset.sampleCount()) + " samples " +
                           std::to_string(dataset.manifest().width) + "x" + std::to_string(dataset.manifest().height) +
                           ", " + errors.describe();
  const BenchDecimation decimation = runBenchDecimation(dataset, errors);
  const SelectionRun& run = decimation.run;
  const DecimationStatistics& statistics = run.statistics;
  const RefinementResult& refinement = run.refinement;
  const std::string cost = collapseCostName(decimation.settings.decimation.cost);
  table.add({"decimation wall time (edge collapse, " + cost + " cost, to the threshold " +
                 formatNumber(decimation.settings.decimation.maxError, 2) + ")",
             size, formatNumber(run.collapseSeconds, 1) + " s",
             "initial edge costs " + formatNumber(run.costingSeconds, 1) + " s, " + std::to_string(run.collapses) +
                 " collapses to " + std::to_string(run.initialSamples - int(run.collapses)) +
                 " samples; loading the panoramas " + formatNumber(decimation.loadSeconds, 1) +
                 " s more; with the refinement, the kernel's page faults " + std::to_string(decimation.pageFaults) +
                 " and system CPU " + formatNumber(decimation.systemSeconds, 1) + " s"});
  // The viewer's live decimation runs the same decimator, one collapse at
  // a time after the initial costing.
  const double collapsing = run.collapseSeconds - run.costingSeconds;
  table.add({"live collapses (the viewer's decimation, after the initial costing)", size,
             formatNumber(collapsing > 0.0 ? double(run.collapses) / collapsing : 0.0, 1) + " collapses/s",
             std::to_string(run.collapses) + " collapses in " + formatNumber(collapsing, 1) +
                 " s, from the dense mesh down to the threshold"});
  table.add({"decimation peak memory (with refinement)", size, formatNumber(decimation.peakGigabytes, 2) + " GiB",
             std::string(decimation.peakIsOwn ? "peak RSS from the load on" : "process peak RSS") +
                 " (the capture before it needs far less): panoramas at the error width plus the "
                 "warped-layer cache (" +
                 formatNumber(decimation.layerBudgetGigabytes, 1) + " GiB budget)"});
  table.add(
      {"decimation errors computed vs served from the cache", size,
       std::to_string(statistics.errorsComputed) + " computed, " + std::to_string(statistics.cacheHits) + " cached",
       "errors of dense samples (" + cost + " cost); warped layers computed " +
           std::to_string(decimation.layersComputed) + " (" + std::to_string(decimation.layersWarpedAgain) +
           " of them again, dropped for the budget), reused " + std::to_string(decimation.layersReused) +
           "; stale heap entries skipped " + std::to_string(statistics.staleEntriesSkipped)});
  table.add({"refinement wall time (references moved at the final count)", size,
             formatNumber(run.refinementSeconds, 1) + " s",
             std::to_string(refinement.moves.size()) + " moves (" + std::to_string(refinement.exchanges) +
                 " exchanges), " + std::to_string(refinement.passes) +
                 " passes of local moves; dense-sample errors computed " + std::to_string(refinement.errorsComputed) +
                 " (" + std::to_string(refinement.exchangeSearchErrors) + " by the exchange searches), cached " + std::to_string(refinement.cacheHits) + "; mean error " +
                 formatNumber(refinement.objectiveBefore, 4) + " -> " + formatNumber(refinement.objectiveAfter, 4)});
}

}  // namespace triwalk
