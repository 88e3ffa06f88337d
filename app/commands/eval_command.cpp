// `triwalk eval`: the paper's Table 1 for a data set and a selection, with
// the baselines at the same sample count.

#include "app/commands/commands.h"
#include "app/setup/decimation_options.h"
#include "app/setup/option_checks.h"
#include "core/io/json_fields.h"
#include "core/io/png_io.h"
#include "core/selection/baselines.h"
#include "core/selection/evaluation.h"
#include "core/selection/selection.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <cstdio>

namespace triwalk {

namespace {

const char* label(const std::string& method) {
  if (method == "initial") return "initial (a)";
  if (method == "uniform") return "uniform (b)";
  if (method == "edge_collapse") return "edge collapse (c)";
  if (method == "kmedoids") return "k-medoids";
  if (method == "random") return "random";
  return method.c_str();
}

void writeHeatmaps(const std::filesystem::path& directory, const MethodEvaluation& evaluation, const ViewMesh& mesh,
                   DatasetTriangleErrors& errors) {
  std::filesystem::create_directories(directory);
  const Dataset& dataset = errors.dataset();
  for (int p = 0; p < dataset.probeCount(); ++p) {
    const Triangle& triangle = mesh.triangles()[size_t(evaluation.probeTriangles[size_t(p)])];
    ScalarImage perPixel;
    errors.errorAt(triangle, dataset.probe(p).position, errors.probeDisplay(p), &perPixel);
    writePng(directory / (evaluation.method + "_p" + std::to_string(dataset.probe(p).id) + ".png"),
             heatmapImage(perPixel, 0.25f));
  }
}

// --counts before any work: each count must be one the collapse log reaches.
void checkCounts(const Dataset& dataset, const Selection& selection, const std::vector<int>& counts) {
  if (counts.empty()) return;
  if (selection.initialTriangles.empty()) {
    throw InputError("--counts", "the selection has no collapse log to replay");
  }
  const int initialCount = ViewMesh(samplePositions(dataset), selection.initialTriangles).vertexCount();
  const int fewest = samplesAfter(initialCount, selection.collapses, selection.collapses.size());
  for (int count : counts) {
    if (count < fewest || count > initialCount) {
      throw InputError("--counts", std::to_string(count) + " samples is outside what the collapse log reaches (" +
                                       std::to_string(fewest) + " to " + std::to_string(initialCount) + ")");
    }
  }
}

// Probe error of edge collapse and the baselines at several sample counts
// (checked by checkCounts): the collapse log replayed to each count gives
// edge collapse's mesh (with the refinement at the final count).
void compareAtCounts(const Dataset& dataset, const Selection& selection, const std::vector<int>& counts, unsigned seed,
                     DatasetTriangleErrors& errors) {
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  const int initialCount = ViewMesh(positions, selection.initialTriangles).vertexCount();
  std::printf("\nprobe mean error by sample count (edge collapse replayed from its log)\n\n");
  std::printf("| samples | edge collapse | uniform | k-medoids | random |\n|---|---|---|---|---|\n");
  double sums[4] = {0, 0, 0, 0};
  for (int count : counts) {
    const size_t steps = *lastStepWithSamples(initialCount, selection.collapses, count);
    const ViewMesh meshes[4] = {
        datasetTriangles(dataset, replayForward(selection.initialTriangles, selection.collapses, steps)),
        datasetMesh(dataset, uniformSelection(dataset, count), "uniform baseline"),
        datasetMesh(dataset, kMedoidsSelection(positions, count), "k-medoids baseline"),
        datasetMesh(dataset, randomSelection(dataset.sampleCount(), count, seed), "random baseline")};
    double values[4];
    for (int m = 0; m < 4; ++m) {
      values[m] = evaluateMesh("", meshes[m], errors).probeMeanError;
      sums[m] += values[m];
    }
    std::printf("| %d | %.4f | %.4f (%d) | %.4f | %.4f |\n", count, values[0], values[1], meshes[1].vertexCount(), values[2],
                values[3]);
  }
  const double n = double(counts.size());
  std::printf("| mean | %.4f | %.4f | %.4f | %.4f |\n", sums[0] / n, sums[1] / n, sums[2] / n, sums[3] / n);
}

}  // namespace

void registerEvalCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, selection, json, heatmaps;
    std::vector<int> counts;
    unsigned seed = 1;
    bool quiet = false;
    ErrorArguments errors;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("eval", "Table 1: edge collapse against the dense set and the baselines");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--selection", arguments->selection, "Edge-collapse selection (from decimate)")->required();
  command->add_option("--json", arguments->json, "Also write the rows as JSON")->check(writableFile());
  command->add_option("--heatmaps", arguments->heatmaps, "Directory for per-probe error heatmap PNGs")->check(writableDirectory());
  command->add_option("--seed", arguments->seed, "Seed of the random baseline")->capture_default_str();
  command->add_option("--counts", arguments->counts,
                      "Also compare probe errors at these sample counts, replaying the selection's collapse log "
                      "(decimate with --target at or below the smallest)")
      ->delimiter(',');
  command->add_flag("--quiet", arguments->quiet, "No progress output");
  addErrorOptions(*command, arguments->errors, TriangleErrorSettings{}.synthesis);

  command->callback([arguments] {
    const Arguments& a = *arguments;
    const Dataset dataset = Dataset::open(a.dataset);
    const Selection selection = readSelection(a.selection, dataset);
    if (dataset.probeCount() == 0) throw InputError(dataset.manifestPath().string(), "eval needs probes (capture --probes N, or import --probes-fraction F)");
    checkCounts(dataset, selection, a.counts);
    const TriangleErrorSettings settings = triangleErrorSettings(a.errors, dataset);
    InterruptScope interruptScope;
    DatasetTriangleErrors errors(dataset, settings, LoadedViews::SamplesAndProbes, a.quiet);

    const std::vector<glm::dvec2> positions = samplePositions(dataset);
    const int count = int(selection.samples.size());
    struct Row {
      std::string method;
      ViewMesh mesh;
    };
    std::vector<Row> rows;
    rows.push_back({"initial", datasetMesh(dataset, {}, a.dataset)});
    rows.push_back({"uniform", datasetMesh(dataset, uniformSelection(dataset, count), "uniform baseline")});
    rows.push_back({"edge_collapse", selectionMesh(selection, dataset)});
    rows.push_back({"kmedoids", datasetMesh(dataset, kMedoidsSelection(positions, count), "k-medoids baseline")});
    rows.push_back({"random", datasetMesh(dataset, randomSelection(dataset.sampleCount(), count, a.seed),
                                                 "random baseline")});

    std::vector<MethodEvaluation> evaluations;
    std::vector<UncoveredPositions> outside;  // the samples a walker finds outside every triangle, by row
    ProgressReporter progress("evaluate", rows.size(), a.quiet);
    for (const Row& row : rows) {
      throwIfInterrupted();
      evaluations.push_back(evaluateMesh(row.method, row.mesh, errors));
      outside.push_back(uncoveredPositions(row.mesh, positions));
      if (!a.heatmaps.empty()) writeHeatmaps(a.heatmaps, evaluations.back(), row.mesh, errors);
      progress.advance();
    }
    progress.finish();

    std::printf("\nTable 1: %s, %d samples, %d probes; %s\n\n", dataset.manifest().scene.c_str(), dataset.sampleCount(),
                dataset.probeCount(), describeErrorSettings(settings).c_str());
    std::printf(
        "| method | samples | triangles | mean error | std. deviation | probe mean error | probe std. deviation | "
        "samples outside every triangle (farthest) |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    for (size_t row = 0; row < evaluations.size(); ++row) {
      const MethodEvaluation& e = evaluations[row];
      std::printf("| %s | %d | %d | %.4f | %.4f | %.4f | %.4f | %d (%.2f m) |\n", label(e.method), e.samples,
                  e.triangles, e.meanError, e.stdError, e.probeMeanError, e.probeStdError, outside[row].count,
                  outside[row].farthest);
    }
    const MethodEvaluation& collapse = evaluations[2];
    std::printf("\nprobe mean error of edge collapse (%.4f) against the baselines: the change, +- one standard error of\n"
                "the probe-by-probe differences, and the probes where edge collapse is lower:\n",
                collapse.probeMeanError);
    for (size_t row : {size_t(1), size_t(3), size_t(4)}) {
      const MethodEvaluation& baseline = evaluations[row];
      const PairedComparison paired = compareProbeErrors(collapse.probeErrors, baseline.probeErrors);
      std::printf("  %-12s %.4f  edge collapse %+.1f%% +- %.1f%%, lower at %d of %zu probes\n", label(baseline.method),
                  baseline.probeMeanError, 100.0 * paired.meanDifference / baseline.probeMeanError,
                  100.0 * paired.standardError / baseline.probeMeanError, paired.candidateLower,
                  collapse.probeErrors.size());
    }

    if (!a.counts.empty()) compareAtCounts(dataset, selection, a.counts, a.seed, errors);

    if (!a.json.empty()) {
      nlohmann::json document = {{"dataset", a.dataset}, {"settings", describeErrorSettings(settings)}, {"rows", nlohmann::json::array()}};
      for (size_t row = 0; row < evaluations.size(); ++row) {
        const MethodEvaluation& e = evaluations[row];
        document["rows"].push_back({{"method", e.method},
                                    {"samples", e.samples},
                                    {"triangles", e.triangles},
                                    {"mean_error", e.meanError},
                                    {"std_error", e.stdError},
                                    {"probe_mean_error", e.probeMeanError},
                                    {"probe_std_error", e.probeStdError},
                                    {"samples_outside", outside[row].count},
                                    {"farthest_outside_m", outside[row].farthest},
                                    {"probe_errors", e.probeErrors}});
      }
      writeJsonFile(a.json, document);
      std::printf("wrote %s\n", a.json.c_str());
    }
  });
}

}  // namespace triwalk
