#include "app/bench/bench_groups.h"
#include "app/bench/temporary_capture.h"

namespace triwalk {

namespace {

struct ScalingRun {
  int samples = 0;
  double captureSeconds = 0.0;
  BenchDecimation decimation;
  double seconds() const { return decimation.run.collapseSeconds + decimation.run.refinementSeconds; }
};

// Captures paths x perPath samples at the error width and decimates them.
ScalingRun decimateCapture(const Scene& scene, int paths, int perPath, const BenchSelectionErrors& errors) {
  CaptureOptions options;
  options.paths = paths;
  options.perPath = perPath;
  options.width = errors.width;  // the decimation reads nothing finer
  options.probes = 0;
  const TemporaryCapture capture(scene, options, "triwalk-bench-scaling-" + std::to_string(paths * perPath));
  ScalingRun result;
  result.samples = capture.summary().samples;
  result.captureSeconds = capture.summary().seconds;
  result.decimation = runBenchDecimation(Dataset::open(capture.directory()), errors);
  return result;
}


}  // namespace

void benchScaling(BenchTable& table, const Scene& scene, const BenchSelectionErrors& errors) {
  const std::string widthText = std::to_string(errors.width) + "x" + std::to_string(errors.width / 2);
  // The default capture's lattice (30 paths x 15), and twice as many paths
  // and samples along each over the same area: 4x the samples at half the
  // spacing, as a denser capture of the same scene would be.
  const ScalingRun runs[2] = {decimateCapture(scene, 30, 15, errors), decimateCapture(scene, 60, 30, errors)};
  for (const ScalingRun& scaling : runs) {
    const SelectionRun& run = scaling.decimation.run;
    table.add({"decimation, " + std::to_string(scaling.samples) + " samples: collapses / refinement",
               std::to_string(scaling.samples) + " samples " + widthText + ", " + errors.describe(),
               formatNumber(run.collapseSeconds, 1) + " s / " + formatNumber(run.refinementSeconds, 1) + " s",
               "peak " + formatNumber(scaling.decimation.peakGigabytes, 2) + " GiB (warped-layer cache budget " +
                   formatNumber(scaling.decimation.layerBudgetGigabytes, 1) + " GiB; layers warped " +
                   std::to_string(scaling.decimation.layersComputed) + ", " +
                   std::to_string(scaling.decimation.layersWarpedAgain) + " of them again); " +
                   std::to_string(run.statistics.errorsComputed) + " + " +
                   std::to_string(run.refinement.errorsComputed) + " errors (" +
                   std::to_string(run.refinement.exchangeSearchErrors) + " by the exchange searches); " +
                   std::to_string(run.collapses) +
                   " collapses, " + std::to_string(run.refinement.moves.size()) + " moves (" +
                   std::to_string(run.refinement.exchanges) + " exchanges); loading " +
                   formatNumber(scaling.decimation.loadSeconds, 1) + " s, capture " +
                   formatNumber(scaling.captureSeconds, 1) + " s"});
  }
  const ScalingRun& small = runs[0];
  const ScalingRun& large = runs[1];
  const std::string sizes =
      std::to_string(small.samples) + " -> " + std::to_string(large.samples) + " samples " + widthText;
  table.add({"decimation time (collapses + refinement) as the capture grows", sizes,
             formatRatio(large.seconds(), small.seconds()),
             formatNumber(small.seconds(), 1) + " -> " + formatNumber(large.seconds(), 1) + " s; collapses " +
                 formatRatio(large.decimation.run.collapseSeconds, small.decimation.run.collapseSeconds) + ", refinement " +
                 formatRatio(large.decimation.run.refinementSeconds, small.decimation.run.refinementSeconds) +
                 "; issue 15's target <= 4.5x"});
  const bool ownPeaks = small.decimation.peakIsOwn && large.decimation.peakIsOwn;
  table.add({"decimation peak memory as the capture grows", sizes,
             formatRatio(large.decimation.peakGigabytes, small.decimation.peakGigabytes),
             formatNumber(small.decimation.peakGigabytes, 2) + " -> " +
                 formatNumber(large.decimation.peakGigabytes, 2) + " GiB" +
                 (ownPeaks ? "" : " (the kernel kept the earlier peak: not each run's own)") +
                 "; issue 15's target <= 4x"});
}

}  // namespace triwalk
