// `triwalk eval`: the paper's Table 1 for a data set and a selection, with
// the baselines at the same sample count.

#include "app/commands/commands.h"
#include "app/setup/decimation_options.h"
#include "app/setup/option_checks.h"
#include "core/image/image_annotation.h"
#include "core/io/json_fields.h"
#include "core/io/png_io.h"
#include "core/selection/baseline_set.h"
#include "core/selection/evaluation.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection.h"
#include "core/selection/tiled_evaluation.h"
#include "core/selection/tiled_selection.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>

namespace triwalk {

namespace {

void writeHeatmaps(const std::filesystem::path& directory, const MethodEvaluation& evaluation, const ViewMesh& mesh,
                   DatasetTriangleErrors& errors) {
  std::filesystem::create_directories(directory);
  const Dataset& dataset = errors.dataset();
  for (int p = 0; p < dataset.probeCount(); ++p) {
    const Triangle& triangle = mesh.triangles()[size_t(evaluation.probeTriangles[size_t(p)])];
    const ScalarImage perPixel = errors.reconstruct(triangle, dataset.probe(p).position, errors.probeDisplay(p)).perPixel;
    writePng(directory / (evaluation.method + "_p" + std::to_string(dataset.probe(p).id) + ".png"),
             withColourBar(heatmapImage(perPixel, 0.25f), 0.25f, "per-pixel RMS colour difference to the probe"));
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
void compareAtCounts(const Dataset& dataset, const Selection& selection, const std::vector<int>& counts,
                     const BaselineSet& baselines, DatasetTriangleErrors& errors) {
  const std::vector<glm::dvec2> positions = samplePositions(dataset);
  const int initialCount = ViewMesh(positions, selection.initialTriangles).vertexCount();
  std::printf("\nprobe mean error by sample count (edge collapse replayed from its log)\n\n");
  std::printf("| samples | edge collapse | uniform | k-medoids | random |\n|---|---|---|---|---|\n");
  // A baseline that cannot be triangulated at a count shows "-" there, and
  // its mean over the counts is left out.
  double sums[4] = {0, 0, 0, 0};
  bool complete[4] = {true, true, true, true};
  for (int count : counts) {
    const size_t steps = *lastStepWithSamples(initialCount, selection.collapses, count);
    const std::function<ViewMesh()> meshes[4] = {
        [&] { return datasetTriangles(dataset, replayForward(selection.initialTriangles, selection.collapses, steps)); },
        [&] { return baselines.mesh("uniform", count); }, [&] { return baselines.mesh("kmedoids", count); },
        [&] { return baselines.mesh("random", count); }};
    std::string cells[4];
    for (int m = 0; m < 4; ++m) {
      std::optional<ViewMesh> mesh;
      try {
        mesh = meshes[m]();
      } catch (const InputError&) {
        if (m == 0) throw;
        complete[m] = false;
        cells[m] = "-";
        continue;
      }
      const double value = evaluateMesh("", *mesh, errors).probeMeanError;
      sums[m] += value;
      char cell[48];
      std::snprintf(cell, sizeof cell, m == 1 ? "%.4f (%d)" : "%.4f", value, mesh->vertexCount());
      cells[m] = cell;
    }
    std::printf("| %d | %s | %s | %s | %s |\n", count, cells[0].c_str(), cells[1].c_str(), cells[2].c_str(),
                cells[3].c_str());
  }
  const double n = double(counts.size());
  std::string means[4];
  for (int m = 0; m < 4; ++m) {
    char cell[32];
    std::snprintf(cell, sizeof cell, "%.4f", sums[m] / n);
    means[m] = complete[m] ? cell : "-";
  }
  std::printf("| mean | %s | %s | %s | %s |\n", means[0].c_str(), means[1].c_str(), means[2].c_str(), means[3].c_str());
}

// The paper's "fewer views for the same quality": how many views each
// geometric baseline needs to reach edge collapse's probe mean, along
// counts from the selection's up to 4 times it, each evaluated only while
// the baseline is still above it. Greedy insertion is left out: each of its
// counts is a selection of its own (the suite interpolates it along its
// rows).
std::vector<std::pair<std::string, ViewsForError>> viewsForEdgeCollapseError(
    const BaselineSet& baselines, const std::vector<MethodEvaluation>& evaluations, int sampleCount, double target,
    const DatasetTriangleErrors& errors) {
  constexpr double kLadder[] = {1.25, 1.5, 2.0, 3.0, 4.0};
  const std::vector<std::string>& geometric = geometricBaselines();
  std::vector<std::pair<std::string, ViewsForError>> views;
  for (const MethodEvaluation& evaluation : evaluations) {
    if (std::find(geometric.begin(), geometric.end(), evaluation.method) == geometric.end()) continue;
    std::vector<std::pair<int, double>> curve = {{evaluation.samples, evaluation.probeMeanError}};
    for (double factor : kLadder) {
      throwIfInterrupted();
      if (curve.back().second <= target) break;
      const int count = std::min(sampleCount, int(std::ceil(factor * double(evaluation.samples))));
      std::optional<ViewMesh> mesh;
      try {
        mesh = baselines.mesh(evaluation.method, count);
      } catch (const InputError&) {
        break;
      }
      if (mesh->vertexCount() <= curve.back().first) continue;
      const std::vector<double> probe = probeErrors(*mesh, errors);
      double mean = 0.0, deviation = 0.0;
      meanAndDeviation(probe, mean, deviation);
      curve.emplace_back(mesh->vertexCount(), mean);
    }
    views.emplace_back(evaluation.method, viewsForError(curve, target));
  }
  return views;
}

}  // namespace

void registerEvalCommand(CLI::App& app) {
  struct Arguments {
    std::string dataset, selection, json, heatmaps, baselinesOut;
    std::vector<int> counts;
    unsigned seed = 1;
    bool quiet = false;
    ErrorArguments errors;
  };
  auto arguments = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand("eval", "Table 1: edge collapse against the dense set and the baselines");
  command->add_option("--dataset", arguments->dataset, "Data set directory")->required();
  command->add_option("--selection", arguments->selection, "Edge-collapse selection (from decimate)")->required();
  command->add_option("--json", arguments->json, "Also write the rows as JSON")->check(writableFile(OutputKind::Evaluation));
  command->add_option("--heatmaps", arguments->heatmaps, "Directory for per-probe error heatmap PNGs")->check(writableDirectory());
  command->add_option("--baselines-out", arguments->baselinesOut,
                      "Also write each baseline at the selection's count as a selection file DIR/METHOD.json, for "
                      "render and view (e.g. to judge their frames with render --truth)")
      ->check(writableDirectory());
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
    if (!a.baselinesOut.empty()) {
      std::vector<std::string> written = geometricBaselines();
      written.insert(written.end(), {"greedy_insertion", "insertion_refined"});
      for (const std::string& method : written) {
        const std::string problem = foreignOutputProblem(std::filesystem::path(a.baselinesOut) / (method + ".json"), OutputKind::Selection);
        if (!problem.empty()) throw InputError("--baselines-out", problem);
      }
    }
    const TriangleErrorSettings settings = triangleErrorSettings(a.errors, dataset);
    InterruptScope interruptScope;
    // A capture larger than a tile is judged tile by tile, never holding
    // every view; heat maps and --counts draw on any view at any time and
    // read them all.
    const bool byTiles = size_t(dataset.sampleCount()) > kTileSamples && a.heatmaps.empty() && a.counts.empty();
    std::unique_ptr<DatasetTriangleErrors> errors;
    if (!byTiles) errors = std::make_unique<DatasetTriangleErrors>(dataset, settings, LoadedViews::SamplesAndProbes, a.quiet);

    const std::vector<glm::dvec2> positions = samplePositions(dataset);
    const int count = int(selection.samples.size());
    const BaselineSet baselines(dataset, a.seed);
    struct Row {
      std::string method;
      ViewMesh mesh;
    };
    std::vector<Row> rows;
    // A baseline that cannot be triangulated at this count (its samples
    // collinear, say) is named with the reason; the rest are evaluated.
    std::vector<std::pair<std::string, std::string>> notBuilt;
    auto addBaseline = [&](const std::string& method) {
      try {
        rows.push_back({method, baselines.mesh(method, count)});
      } catch (const InputError& error) {
        notBuilt.emplace_back(method, error.problem());
      }
    };
    rows.push_back({"initial", datasetMesh(dataset, {}, a.dataset)});
    addBaseline("uniform");
    rows.push_back({"edge_collapse", selectionMesh(selection, dataset)});
    for (const std::string& method : geometricBaselines()) {
      if (method != "uniform") addBaseline(method);
    }
    // Greedy insertion, alone and refined, with the errors the selection
    // was made with; it prices every free sample at every step, so not on
    // a capture judged by tiles.
    if (byTiles) {
      notBuilt.emplace_back("greedy_insertion", "not run above " + std::to_string(kTileSamples) +
                                                    " samples (it prices every free sample at every step)");
    } else if (!selection.errors) {
      notBuilt.emplace_back("greedy_insertion", "the selection file does not say which errors it was made with");
    } else {
      DatasetTriangleErrors selectionErrors(dataset, *selection.errors, LoadedViews::Samples, a.quiet);
      const InsertionRun run =
          insertReferences(dataset, selectionErrors, RefinementOptions{}, insertionStartCount(count), count, a.quiet);
      rows.push_back({"greedy_insertion", datasetMesh(dataset, run.referencesAt(count), "greedy insertion")});
      rows.push_back({"insertion_refined", datasetTriangles(dataset, refinedReferences(dataset, selectionErrors, RefinementOptions{},
                                                                                        run.referencesAt(count), a.quiet))});
    }

    if (!a.baselinesOut.empty()) {
      std::filesystem::create_directories(a.baselinesOut);
      for (const Row& row : rows) {
        if (row.method == "initial" || row.method == "edge_collapse") continue;
        Selection baseline;
        baseline.method = row.method;
        baseline.samples = row.mesh.vertices();
        baseline.triangles = row.mesh.triangles();
        writeSelection(std::filesystem::path(a.baselinesOut) / (row.method + ".json"), baseline, dataset);
      }
    }

    std::vector<MethodEvaluation> evaluations;
    std::vector<UncoveredPositions> outside;  // the samples a walker finds outside every triangle, by row
    for (const Row& row : rows) outside.push_back(uncoveredPositions(row.mesh, positions));
    if (byTiles) {
      std::vector<NamedMesh> meshes;
      for (const Row& row : rows) meshes.push_back({row.method, &row.mesh});
      evaluations = evaluateMeshesInTiles(dataset, meshes, settings, kTileSamples, a.quiet);
    } else {
      ProgressReporter progress("evaluate", rows.size(), a.quiet);
      for (const Row& row : rows) {
        throwIfInterrupted();
        evaluations.push_back(evaluateMesh(row.method, row.mesh, *errors));
        if (!a.heatmaps.empty()) writeHeatmaps(a.heatmaps, evaluations.back(), row.mesh, *errors);
        progress.advance();
      }
      progress.finish();
    }
    const auto collapse = std::find_if(evaluations.begin(), evaluations.end(),
                                       [](const MethodEvaluation& e) { return e.method == "edge_collapse"; });

    std::printf("\nTable 1: %s, %d samples, %d probes; %s\n\n", dataset.manifest().scene.c_str(), dataset.sampleCount(),
                dataset.probeCount(), describeErrorSettings(settings).c_str());
    std::printf(
        "| method | samples | triangles | mean error | std. deviation | probe mean error | probe std. deviation | "
        "samples outside every triangle (farthest) |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    for (size_t row = 0; row < evaluations.size(); ++row) {
      const MethodEvaluation& e = evaluations[row];
      std::printf("| %s | %d | %d | %.4f | %.4f | %.4f | %.4f | %d (%.2f m) |\n", methodLabel(e.method), e.samples,
                  e.triangles, e.meanError, e.stdError, e.probeMeanError, e.probeStdError, outside[row].count,
                  outside[row].farthest);
    }
    for (const auto& [method, reason] : notBuilt) {
      std::printf("| %s | not built at %d samples: %s |\n", methodLabel(method), count, reason.c_str());
    }
    std::printf("\nprobe mean error of edge collapse (%.4f) against the baselines: the change, +- one standard error of\n"
                "the probe-by-probe differences, and the probes where edge collapse is lower:\n",
                collapse->probeMeanError);
    for (const MethodEvaluation& baseline : evaluations) {
      if (baseline.method == "initial" || baseline.method == "edge_collapse") continue;
      const PairedComparison paired = compareProbeErrors(collapse->probeErrors, baseline.probeErrors);
      std::printf("  %-24s %.4f  edge collapse %+.1f%% +- %.1f%%, lower at %d of %zu probes\n", methodLabel(baseline.method),
                  baseline.probeMeanError, 100.0 * paired.meanDifference / baseline.probeMeanError,
                  100.0 * paired.standardError / baseline.probeMeanError, paired.candidateLower,
                  collapse->probeErrors.size());
    }

    std::vector<std::pair<std::string, ViewsForError>> views;
    if (!byTiles) {
      views = viewsForEdgeCollapseError(baselines, evaluations, dataset.sampleCount(), collapse->probeMeanError, *errors);
      std::printf("\nviews each baseline needs for edge collapse's probe mean (%.4f with %d views), interpolated\n"
                  "along its counts up to 4 times as many:\n",
                  collapse->probeMeanError, collapse->samples);
      for (const auto& [method, needed] : views) {
        std::printf("  %-24s %s\n", methodLabel(method), formatViews(needed).c_str());
      }
    }

    if (!a.counts.empty()) compareAtCounts(dataset, selection, a.counts, baselines, *errors);

    if (!a.json.empty()) {
      nlohmann::json document = {{"format", outputFormat(OutputKind::Evaluation)},
                                 {"dataset", a.dataset},
                                 {"settings", describeErrorSettings(settings)},
                                 {"rows", nlohmann::json::array()},
                                 {"not_built", nlohmann::json::object()}};
      for (const auto& [method, reason] : notBuilt) document["not_built"][method] = reason;
      for (const auto& [method, needed] : views) {
        document["views_for_edge_collapse_error"][method] = formatViews(needed);
      }
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
