// `triwalk suite`: the selection measured on several scenes at several
// sample counts. Each scene is captured once (if its data set is missing),
// decimated on its own at each count (--target N, refinement included:
// what a user gets), and compared at its held-out probes with the dense
// triangulation and the baselines. One table: per scene and count, the
// probe mean of every method, edge collapse's paired difference against
// uniform and k-medoids with its standard error, and the fraction of the
// uniform -> dense gap that edge collapse closes; then the means over
// scenes.
//
// The spec file (JSON):
// {
//   "format": "triwalk-suite", "width": 512, "probes": 100,
//   "fractions": [0.05, 0.1, 0.2],                 (of each scene's samples)
//   "scenes": [ {"name": "builtin", "scene": "builtin"},
//               {"name": "oacmpdm2", "scene": ".../z_oacmp-volume1-v3.pk3", "map": "oacmpdm2"}, ... ]
// }

#include "app/commands/commands.h"
#include "app/setup/decimation_options.h"
#include "app/setup/option_checks.h"
#include "app/setup/scene_capture.h"
#include "app/setup/selection_preset.h"
#include "app/setup/tile_jobs.h"
#include "core/io/atomic_file.h"
#include "core/io/json_fields.h"
#include "core/selection/baseline_set.h"
#include "core/selection/evaluation.h"
#include "core/selection/reference_selection.h"
#include "core/selection/tiled_selection.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace triwalk {

namespace {

struct SuiteScene {
  std::string name;
  SceneCaptureRequest capture;
};

struct SuiteSpec {
  int width = 512;
  int probes = 100;
  std::vector<double> fractions;
  std::vector<SuiteScene> scenes;
};

SuiteSpec readSuiteSpec(const std::filesystem::path& path) {
  const nlohmann::json document = readJsonFile(path);
  const JsonObject root(document, path.string());
  if (root.stringOr("format", "") != "triwalk-suite") root.fail("not a triwalk suite (format field)");
  SuiteSpec spec;
  spec.width = root.integerOr("width", spec.width);
  spec.probes = root.integerOr("probes", spec.probes);
  if (spec.width < 16 || spec.width % 2 != 0) root.fail("width: must be an even number >= 16");
  if (spec.probes < 2) root.fail("probes: a paired comparison needs at least 2 probes");
  const nlohmann::json& fractions = root.array("fractions");
  for (size_t i = 0; i < fractions.size(); ++i) {
    if (!fractions[i].is_number() || !(fractions[i].get<double>() > 0.0 && fractions[i].get<double>() < 1.0)) {
      root.fail("fractions[" + std::to_string(i) + "]: a fraction of the samples, between 0 and 1");
    }
    spec.fractions.push_back(fractions[i].get<double>());
  }
  if (spec.fractions.empty()) root.fail("fractions: give at least one");
  const nlohmann::json& scenes = root.array("scenes");
  std::set<std::string> names;
  for (size_t i = 0; i < scenes.size(); ++i) {
    const JsonObject entry = root.element("scenes", i);
    SuiteScene scene;
    scene.name = entry.string("name");
    if (scene.name.empty() || scene.name.find_first_of("/\\") != std::string::npos || scene.name[0] == '.') {
      entry.fail("name: a plain folder name");
    }
    if (!names.insert(scene.name).second) entry.fail("name: '" + scene.name + "' appears twice");
    scene.capture.scene = entry.string("scene");
    scene.capture.import.map = entry.stringOr("map", "");
    if (entry.has("area")) scene.capture.options.area = entry.vec4("area");
    scene.capture.options.width = spec.width;
    scene.capture.options.probes = spec.probes;
    spec.scenes.push_back(std::move(scene));
  }
  if (spec.scenes.empty()) root.fail("scenes: give at least one");
  return spec;
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return values.empty() ? 0.0 : sum / double(values.size());
}

// Edge collapse against one baseline at the probes: the paired difference
// relative to the baseline's mean.
struct Comparison {
  double relative = 0.0, standardError = 0.0;
};

Comparison compare(const std::vector<double>& candidate, const std::vector<double>& baseline) {
  const PairedComparison paired = compareProbeErrors(candidate, baseline);
  const double baselineMean = mean(baseline);
  return {paired.meanDifference / baselineMean, paired.standardError / baselineMean};
}

// The methods edge collapse is compared with, in the tables' order: the
// geometric baselines, then greedy insertion alone and refined.
std::vector<std::string> comparedMethods() {
  std::vector<std::string> methods = geometricBaselines();
  methods.push_back("greedy_insertion");
  methods.push_back("insertion_refined");
  return methods;
}

struct SuiteRow {
  std::string scene;
  double fraction = 0.0;
  int count = 0;         // the target
  int reachedCount = 0;  // edge collapse's references, which every other method gets too
  int uniformCount = 0;
  double dense = 0.0, edgeCollapse = 0.0;
  // Per compared method: its probe mean (NaN where it could not be
  // triangulated at the count), edge collapse against it, and the views
  // it needs for edge collapse's probe mean along the scene's rows.
  std::map<std::string, double> means;
  std::map<std::string, Comparison> versus;
  std::map<std::string, ViewsForError> views;
  double gapClosed = 0.0;  // (uniform - edge collapse) / (uniform - dense)
  double selectionSeconds = 0.0;
};

std::string formatPercent(const Comparison& comparison) {
  char text[48];
  std::snprintf(text, sizeof text, "%+.1f%% +- %.1f%%", 100.0 * comparison.relative, 100.0 * comparison.standardError);
  return text;
}

std::string formatMean(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4f", value);
  return std::isnan(value) ? "-" : text;
}

std::string samplesCell(const SuiteRow& r) {
  return r.reachedCount == r.count ? std::to_string(r.count)
                                   : std::to_string(r.reachedCount) + " (target " + std::to_string(r.count) + ")";
}

// A table's header and rule: the first columns ("a | b"), a column per
// method, and a last column if named.
std::string headerOf(const std::string& first, const std::vector<std::string>& methods, const std::string& prefix,
                     const std::string& last = "") {
  std::string header = "| " + first, rule = "|---";
  for (const char c : first) rule += c == '|' ? "|---" : "";
  for (const std::string& method : methods) header += " | " + prefix + methodLabel(method), rule += "|---";
  if (!last.empty()) header += " | " + last, rule += "|---";
  return header + " |\n" + rule + "|\n";
}

// Three tables, a row per scene and count: the probe means; edge collapse
// against each method, paired; the views each method needs for edge
// collapse's probe mean. Then the means over scenes.
std::string tableOf(const std::vector<SuiteRow>& rows, const std::vector<double>& fractions) {
  const std::vector<std::string> methods = comparedMethods();
  std::ostringstream out;
  out << "Probe mean error (uniform: its own count in brackets):\n\n"
      << headerOf("scene | samples | dense | edge collapse", methods, "", "gap closed");
  for (const SuiteRow& r : rows) {
    out << "| " << r.scene << " | " << samplesCell(r) << " | " << formatMean(r.dense) << " | " << formatMean(r.edgeCollapse);
    for (const std::string& method : methods) {
      out << " | " << formatMean(r.means.at(method));
      if (method == "uniform") out << " (" << r.uniformCount << ")";
    }
    char gap[16];
    std::snprintf(gap, sizeof gap, "%.0f%%", 100.0 * r.gapClosed);
    out << " | " << gap << " |\n";
  }
  out << "\nEdge collapse against each method, probe by probe (negative: edge collapse lower; +- one standard "
         "error of the paired differences):\n\n"
      << headerOf("scene | samples", methods, "vs ");
  for (const SuiteRow& r : rows) {
    out << "| " << r.scene << " | " << samplesCell(r);
    for (const std::string& method : methods) {
      out << " | " << (std::isnan(r.means.at(method)) ? "-" : formatPercent(r.versus.at(method)));
    }
    out << " |\n";
  }
  out << "\nViews each method needs for edge collapse's probe mean at the row's count, interpolated along the "
         "scene's rows (<= : already at the row's count or below; > : not at the scene's largest count):\n\n"
      << headerOf("scene | edge collapse", methods, "");
  for (const SuiteRow& r : rows) {
    out << "| " << r.scene << " | " << r.reachedCount;
    for (const std::string& method : methods) {
      out << " | " << (r.views.count(method) ? formatViews(r.views.at(method)) : "-");
    }
    out << " |\n";
  }
  out << "\nMeans over scenes of edge collapse against each method, and the rows where edge collapse has the "
         "lower probe mean:\n\n"
      << headerOf("fraction", methods, "vs ", "gap closed");
  auto summary = [&](const std::string& label, const std::vector<const SuiteRow*>& selected) {
    out << "| " << label;
    for (const std::string& method : methods) {
      double relative = 0.0;
      int wins = 0, rowsBuilt = 0;
      for (const SuiteRow* r : selected) {
        if (std::isnan(r->means.at(method))) continue;
        relative += r->versus.at(method).relative;
        wins += r->edgeCollapse < r->means.at(method);
        ++rowsBuilt;
      }
      char cell[64];
      std::snprintf(cell, sizeof cell, "%+.1f%% (%d of %d)", rowsBuilt ? 100.0 * relative / rowsBuilt : 0.0, wins,
                    rowsBuilt);
      out << " | " << cell;
    }
    double gap = 0.0;
    for (const SuiteRow* r : selected) gap += r->gapClosed / double(selected.size());
    char cell[16];
    std::snprintf(cell, sizeof cell, "%.0f%%", 100.0 * gap);
    out << " | " << cell << " |\n";
  };
  std::vector<const SuiteRow*> all;
  for (double fraction : fractions) {
    std::vector<const SuiteRow*> selected;
    for (const SuiteRow& r : rows) {
      if (r.fraction == fraction) selected.push_back(&r);
    }
    char label[32];
    std::snprintf(label, sizeof label, "%.0f%%", 100.0 * fraction);
    if (!selected.empty()) summary(label, selected);
  }
  for (const SuiteRow& r : rows) all.push_back(&r);
  if (!all.empty()) summary("all", all);
  return out.str();
}

// Each row's views for edge collapse's probe mean, along the scene's rows
// of each method (its probe mean at each row's count).
void addViewsForEqualError(std::vector<SuiteRow>& rows, size_t firstOfScene) {
  for (const std::string& method : comparedMethods()) {
    std::vector<std::pair<int, double>> curve;
    for (size_t i = firstOfScene; i < rows.size(); ++i) {
      const double value = rows[i].means.at(method);
      const int count = method == "uniform" ? rows[i].uniformCount : rows[i].reachedCount;
      if (!std::isnan(value) && (curve.empty() || count > curve.back().first)) curve.emplace_back(count, value);
    }
    if (curve.empty()) continue;
    for (size_t i = firstOfScene; i < rows.size(); ++i) rows[i].views[method] = viewsForError(curve, rows[i].edgeCollapse);
  }
}

}  // namespace

void registerSuiteCommand(CLI::App& app) {
  struct Arguments {
    std::string spec, out;
    std::vector<std::string> only;
    bool reuseSelections = false;
    bool quiet = false;
    int tiles = 1;
    std::string preset = "default";
    SelectionArguments selection;
    std::string selectionBlendWeights, selectionSourceMesh;  // decimate's defaults, set below
    int selectionErrorWidth = 0;  // 0: the evaluation's
    ErrorArguments errors;
  };
  auto arguments = std::make_shared<Arguments>();
  const SynthesisOptions selectionDefaults = withSelectionDefaults(TriangleErrorSettings{}.synthesis);
  arguments->selectionBlendWeights = blendWeightsName(selectionDefaults.blend.weights);
  arguments->selectionSourceMesh = sourceMeshName(selectionDefaults.warp.mesh);
  CLI::App* command =
      app.add_subcommand("suite", "Measure the selection against the baselines on several scenes and sample counts");
  command->add_option("--spec", arguments->spec, "Suite file (JSON: scenes, capture width, probes, count fractions)")
      ->required();
  command->add_option("--out", arguments->out, "Directory for the data sets, selections and the table")->required()->check(writableDirectory());
  command->add_option("--only", arguments->only, "Run only these scenes (names from the spec)")->delimiter(',');
  command->add_flag("--reuse-selections", arguments->reuseSelections,
                    "Evaluate selections already in --out instead of decimating again");
  command->add_flag("--quiet", arguments->quiet, "No progress output from the steps");
  command->add_option("--tiles", arguments->tiles,
                      "Select each count in this many tiles, stitched (decimate --tiles N), to measure the tiled "
                      "selection against one decimation; default 1: one decimation")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  // Before the options it sets, so that those given beside it override it.
  command
      ->add_option_function<std::string>(
          "--preset",
          [arguments](const std::string& name) {
            applySelectionPreset(name, arguments->selection);
            if (name == "paper") arguments->selectionBlendWeights = "distance";
            arguments->preset = name;
          },
          "How every count is selected, as decimate --preset selects (default, paper or fast; the suite stops at "
          "its counts, not at the paper's threshold); the evaluation stays the same")
      ->check(CLI::IsMember({"default", "paper", "fast"}));
  addSelectionOptions(*command, arguments->selection);
  command->add_option("--selection-blend-weights", arguments->selectionBlendWeights,
                      "Blend weights of the errors the selection is made with (--blend-weights: those it is "
                      "evaluated with)")
      ->capture_default_str()->check(CLI::IsMember({"reliability", "distance"}));
  command
      ->add_option("--selection-source-mesh", arguments->selectionSourceMesh,
                   "Source meshes of the errors the selection is made with (--source-mesh: those it is "
                   "evaluated with)")
      ->capture_default_str()
      ->check(CLI::IsMember({"simplified", "grid"}));
  command
      ->add_option("--selection-error-width", arguments->selectionErrorWidth,
                   "Panorama width of the errors the selection is made with (default: --error-width, the "
                   "evaluation's)")
      ->check(nonNegativeNumber());
  addErrorOptions(*command, arguments->errors, TriangleErrorSettings{}.synthesis);

  command->callback([arguments] {
    const Arguments& a = *arguments;
    const SuiteSpec spec = readSuiteSpec(a.spec);
    for (const std::string& name : a.only) {
      if (std::none_of(spec.scenes.begin(), spec.scenes.end(), [&](const SuiteScene& s) { return s.name == name; })) {
        throw InputError("--only", "no scene '" + name + "' in " + a.spec);
      }
    }
    // The selection's errors: the evaluation's, with the preset's rules.
    ErrorArguments selectionErrorArguments = a.errors;
    applyPresetErrorRules(a.preset, selectionErrorArguments);
    {
      // --error-stride against the options, before anything is written.
      TriangleErrorSettings selectionLattice;
      selectionLattice.synthesis = synthesisOptions(selectionErrorArguments.quality);
      applyErrorStride(a.selection, selectionLattice);
    }
    const std::filesystem::path out = a.out;
    std::error_code error;
    std::filesystem::create_directories(out, error);
    if (error) throw InputError(a.out, "cannot create the directory: " + error.message());
    std::printf("suite %s: %zu scenes\n", a.spec.c_str(), spec.scenes.size());

    InterruptScope interruptScope;
    std::vector<SuiteRow> rows;
    nlohmann::json results = nlohmann::json::array();
    const size_t steps = spec.scenes.size() * spec.fractions.size();
    ProgressReporter progress("suite", steps, false);
    for (const SuiteScene& scene : spec.scenes) {
      if (!a.only.empty() && std::find(a.only.begin(), a.only.end(), scene.name) == a.only.end()) {
        progress.advance(spec.fractions.size());
        continue;
      }
      const std::filesystem::path directory = out / scene.name;
      const std::filesystem::path datasetDirectory = directory / "dataset";
      if (!std::filesystem::exists(datasetDirectory / kManifestFileName)) {
        std::printf("== %s: capture\n", scene.name.c_str());
        SceneCaptureRequest capture = scene.capture;
        capture.out = datasetDirectory.string();
        capture.options.quiet = a.quiet;
        captureScene(capture);
      }
      const Dataset dataset = Dataset::open(datasetDirectory);
      if (dataset.probeCount() < 2) throw InputError(dataset.manifestPath().string(), "the suite needs probes");
      const TriangleErrorSettings settings = triangleErrorSettings(a.errors, dataset);
      TriangleErrorSettings selectionErrorSettings = triangleErrorSettings(selectionErrorArguments, dataset);
      selectionErrorSettings.synthesis.blend.weights = parseBlendWeights(a.selectionBlendWeights);
      selectionErrorSettings.synthesis.warp.mesh = parseSourceMesh(a.selectionSourceMesh);
      applyErrorStride(a.selection, selectionErrorSettings);
      if (a.selectionErrorWidth > 0) {
        dataset.downsamplingFactor(a.selectionErrorWidth, "--selection-error-width");
        selectionErrorSettings.width = a.selectionErrorWidth;
      }
      std::printf("== %s: selection with %s\n== %s: evaluation with %s\n", scene.name.c_str(),
                  describeErrorSettings(selectionErrorSettings).c_str(), scene.name.c_str(),
                  describeErrorSettings(settings).c_str());

      // Every count's selection first, with the selection's errors; then
      // the evaluation's, so only one set of panoramas and warp cache is
      // held at a time.
      std::vector<int> counts;
      std::vector<Selection> selections;
      std::vector<double> selectionSeconds;
      std::vector<std::pair<Selection, Selection>> inserted;  // greedy insertion, alone and refined, per count
      {
        std::optional<DatasetTriangleErrors> selectionErrors;  // loaded when a count needs selecting
        for (double fraction : spec.fractions) {
          throwIfInterrupted();
          const int count = std::max(4, int(std::lround(fraction * dataset.sampleCount())));
          const std::filesystem::path selectionFile = directory / ("selection_" + std::to_string(count) + ".json");
          counts.push_back(count);
          selectionSeconds.push_back(0.0);
          if (a.reuseSelections && std::filesystem::exists(selectionFile)) {
            selections.push_back(readSelection(selectionFile, dataset));
            continue;
          }
          std::printf("== %s: selecting %d of %d samples\n", scene.name.c_str(), count, dataset.sampleCount());
          std::fflush(stdout);
          const SelectionSettings selectionOptions = selectionSettings(a.selection, 0.0, count);
          if (a.tiles > 1) {
            const auto began = std::chrono::steady_clock::now();
            const TilePlanRequest request{describeSelectionRecipe({selectionErrorSettings, selectionOptions, a.preset}), a.tiles,
                                          defaultJobs()};
            const std::filesystem::path work = std::filesystem::path(selectionFile).concat(".tiles");
            std::optional<StitchResult> stitched = decimateInTiles(dataset, request, work, a.quiet);
            TRIWALK_CHECK(stitched.has_value(), "the suite runs its tiles in its own process");
            writeSelection(selectionFile, stitched->selection, dataset);
            std::filesystem::remove_all(work);
            selections.push_back(std::move(stitched->selection));
            selectionSeconds.back() = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
            continue;
          }
          if (!selectionErrors) selectionErrors.emplace(dataset, selectionErrorSettings, LoadedViews::Samples, a.quiet);
          SelectionRun run = selectReferences(dataset, *selectionErrors, selectionOptions, a.quiet);
          run.selection.settings = describeSelectionRecipe({selectionErrorSettings, selectionOptions, a.preset});
          writeSelection(selectionFile, run.selection, dataset);
          selections.push_back(std::move(run.selection));
          selectionSeconds.back() = run.collapseSeconds + run.refinementSeconds;
        }
        // Greedy insertion at each row's count (edge collapse's), alone
        // and refined, by the same errors and refinement settings; saved
        // beside edge collapse's selections.
        for (size_t f = 0; f < counts.size(); ++f) {
          throwIfInterrupted();
          const int reached = int(selections[f].samples.size());
          const SelectionSettings selectionOptions = selectionSettings(a.selection, 0.0, counts[f]);
          auto fileOf = [&](const std::string& method) {
            return directory / (method + "_" + std::to_string(counts[f]) + ".json");
          };
          if (a.reuseSelections && std::filesystem::exists(fileOf("greedy_insertion")) &&
              std::filesystem::exists(fileOf("insertion_refined"))) {
            std::pair<Selection, Selection> earlier = {readSelection(fileOf("greedy_insertion"), dataset),
                                                       readSelection(fileOf("insertion_refined"), dataset)};
            if (int(earlier.first.samples.size()) == reached && int(earlier.second.samples.size()) == reached) {
              inserted.push_back(std::move(earlier));
              continue;
            }
          }
          std::printf("== %s: greedy insertion of %d of %d samples\n", scene.name.c_str(), reached,
                      dataset.sampleCount());
          std::fflush(stdout);
          if (!selectionErrors) selectionErrors.emplace(dataset, selectionErrorSettings, LoadedViews::Samples, a.quiet);
          const InsertionRun run = insertReferences(dataset, *selectionErrors, selectionOptions.refinement,
                                                    insertionStartCount(reached), reached, a.quiet);
          auto saved = [&](const std::string& method, const ViewMesh& mesh) {
            Selection selection;
            selection.method = method;
            selection.samples = mesh.vertices();
            selection.triangles = mesh.triangles();
            selection.settings = describeSelectionRecipe({selectionErrorSettings, selectionOptions, a.preset});
            writeSelection(fileOf(method), selection, dataset);
            return selection;
          };
          const std::vector<int> references = run.referencesAt(reached);
          const Selection greedy = saved("greedy_insertion", datasetMesh(dataset, references, "greedy insertion"));
          const Selection refined = saved(
              "insertion_refined", datasetTriangles(dataset, refinedReferences(dataset, *selectionErrors,
                                                                               selectionOptions.refinement, references, a.quiet)));
          inserted.push_back({greedy, refined});
        }
      }

      DatasetTriangleErrors errors(dataset, settings, LoadedViews::SamplesAndProbes, a.quiet);
      const BaselineSet baselines(dataset, 1);
      const std::vector<double> dense = probeErrors(datasetMesh(dataset, {}, dataset.manifestPath().string()), errors);
      const size_t firstOfScene = rows.size();
      std::vector<nlohmann::json> sceneResults;
      for (size_t f = 0; f < spec.fractions.size(); ++f) {
        throwIfInterrupted();
        const double fraction = spec.fractions[f];
        const int count = counts[f];
        const Selection& selection = selections[f];
        SuiteRow row;
        row.scene = scene.name;
        row.fraction = fraction;
        row.count = count;
        row.selectionSeconds = selectionSeconds[f];
        // The decimation can stop off its target: above it when no valid
        // collapse is left (a level whose parts and corridors each need
        // their own triangles), below it when a collapse also drops a
        // boundary sample. The other methods get as many references as
        // edge collapse kept, so every row compares equal counts.
        const int reached = int(selection.samples.size());
        row.reachedCount = reached;
        const std::vector<double> edgeCollapse = probeErrors(selectionMesh(selection, dataset), errors);
        nlohmann::json probeErrorsJson = {{"dense", dense}, {"edge_collapse", edgeCollapse}};
        for (const std::string& method : comparedMethods()) {
          // A baseline that cannot be triangulated at the count is named "-", as eval does.
          std::vector<double> values;
          if (method == "greedy_insertion" || method == "insertion_refined") {
            const Selection& insertion = method == "greedy_insertion" ? inserted[f].first : inserted[f].second;
            values = probeErrors(selectionMesh(insertion, dataset), errors);
          } else {
            try {
              const ViewMesh mesh = baselines.mesh(method, reached);
              if (method == "uniform") row.uniformCount = mesh.vertexCount();
              values = probeErrors(mesh, errors);
            } catch (const InputError&) {
            }
          }
          row.means[method] = values.empty() ? std::nan("") : mean(values);
          if (!values.empty()) row.versus[method] = compare(edgeCollapse, values);
          probeErrorsJson[method] = values;
        }
        row.dense = mean(dense);
        row.edgeCollapse = mean(edgeCollapse);
        row.gapClosed = (row.means.at("uniform") - row.edgeCollapse) / (row.means.at("uniform") - row.dense);
        std::printf("   edge collapse %.4f, uniform %.4f (%d), greedy insertion refined %s: %s against uniform, %s "
                    "against greedy insertion refined, %.0f%% of the gap closed\n",
                    row.edgeCollapse, row.means.at("uniform"), row.uniformCount,
                    formatMean(row.means.at("insertion_refined")).c_str(), formatPercent(row.versus["uniform"]).c_str(),
                    formatPercent(row.versus["insertion_refined"]).c_str(), 100.0 * row.gapClosed);
        std::fflush(stdout);
        sceneResults.push_back({{"scene", scene.name},
                                {"settings", selection.settings},
                                {"fraction", fraction},
                                {"samples", count},
                                {"edge_collapse_samples", reached},
                                {"uniform_samples", row.uniformCount},
                                {"selection", "selection_" + std::to_string(count) + ".json"},
                                {"selection_seconds", row.selectionSeconds},
                                {"probe_errors", probeErrorsJson}});
        rows.push_back(row);
        progress.advance();
      }
      addViewsForEqualError(rows, firstOfScene);
      for (size_t i = 0; i < sceneResults.size(); ++i) {
        for (const auto& [method, views] : rows[firstOfScene + i].views) {
          sceneResults[i]["views_for_edge_collapse_error"][method] = formatViews(views);
        }
        results.push_back(std::move(sceneResults[i]));
      }
    }
    progress.finish();
    const std::string table = tableOf(rows, spec.fractions);
    std::printf("\n%s", table.c_str());
    writeJsonFile(out / "suite.json", {{"spec", a.spec}, {"rows", results}});
    writeTextFileAtomically(out / "suite.md", table);
    std::printf("wrote %s and %s\n", (out / "suite.md").c_str(), (out / "suite.json").c_str());
  });
}

}  // namespace triwalk
