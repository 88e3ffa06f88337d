// The command line as a user meets it: bad options fail with one line on
// stderr and a non-zero status before any work, leaving no output behind;
// defaults fit the data set they are given.

#include "app/video/video_file.h"
#include "core/io/atomic_file.h"
#include "core/io/dataset.h"
#include "core/selection/reference_selection.h"
#include "core/selection/selection.h"
#include "core/selection/selection_inputs.h"
#include "tests/analytic_scene.h"
#include "tests/command_line_runner.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace triwalk {

using testing::kTriwalkWithOpenGl;
using testing::RunResult;
using testing::runTriwalk;

TEST_CASE("bad options fail in one line naming the option, before any work, and write nothing") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 64, 1);
  const std::string data = " --dataset " + (directory / "data").string();
  const std::string selection = (directory / "selection.json").string();
  const std::string frames = (directory / "frames").string();
  struct Case {
    std::string arguments, message;
  };
  const std::vector<Case> cases = {
      {"decimate" + data + " --out " + selection + " --max-error nan", "--max-error: must be a finite number, got nan"},
      {"decimate" + data + " --out " + selection + " --max-error inf", "--max-error: must be a finite number, got inf"},
      {"decimate" + data + " --out " + selection + " --max-error -1", "--max-error: must be from 1e-09 to 1e+09, got -1"},
      {"decimate" + data + " --out " + selection + " --relative-error 0", "--relative-error: must be from 1e-06 to 1e+06, got 0"},
      {"decimate" + data + " --out " + selection + " --relative-error nan", "--relative-error: must be a finite number, got nan"},
      {"decimate" + data + " --out " + selection + " --max-error 1.5 --relative-error 1.2",
       "--max-error excludes --relative-error"},
      {"decimate" + data + " --out " + selection + " --refine-radius NaN", "--refine-radius: must be a finite number"},
      {"decimate" + data + " --out /nonexistent/folder/selection.json --target 4", "--out: cannot write /nonexistent/folder"},
      {"decimate" + data + " --out " + (directory / "data").string() + " --target 4", "is a folder, not a file"},
      {"decimate" + data + " --out " + selection + " --target 4 --error-width 100", "--error-width: width 100 must divide"},
      {"decimate" + data + " --out " + selection + " --target 4 --no-such-option", "--no-such-option"},
      {"decimate" + data + " --out " + selection + " --target 4 --error-stride 3", "--error-stride: 3 not in {1,2,4}"},
      {"decimate" + data + " --out " + selection + " --target 4 --error-stride 2 --holes fill",
       "--error-stride: a lattice of pixels cannot be hole-filled"},
      {"render" + data + " --out " + frames + " --fov nan", "--fov: must be a finite number"},
      {"render" + data + " --out " + frames + " --pitch -inf", "--pitch: must be a finite number"},
      {"render" + data + " --out /proc/version/frames", "--out: cannot create folder /proc/version/frames"},
      {"capture --out " + (directory / "new").string() + " --spacing nan", "--spacing: must be a finite number, got nan"},
      {"capture --out " + (directory / "new").string() + " --area 0,0,nan,1", "--area: must be a finite number"},
      {"eval" + data + " --selection " + selection + " --json /nonexistent/rows.json", "--json: cannot write"},
      {"bench --only capture --capture-views 4", "--capture-views: Value 4 not in range 8 to 100000"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.arguments);
    const RunResult result = runTriwalk(directory, c.arguments);
    INFO("stderr: " << result.err);
    CHECK(result.status != 0);
    CHECK(result.err.find(c.message) != std::string::npos);
    CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 1);
    CHECK(result.out.empty());
    CHECK_FALSE(std::filesystem::exists(selection));
    CHECK_FALSE(std::filesystem::exists(frames));
    CHECK_FALSE(std::filesystem::exists(directory / "new"));
  }
}

TEST_CASE("decimate on a data set narrower than the default error width computes its errors at the data set's width") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 128, 1);
  const RunResult result = runTriwalk(directory, "decimate --quiet --target 4 --refine-radius 0 --dataset " +
                                                     (directory / "data").string() + " --out " +
                                                     (directory / "selection.json").string());
  INFO("stderr: " << result.err);
  REQUIRE(result.status == 0);
  CHECK(result.out.find("errors at 128x64") != std::string::npos);
  CHECK(result.out.find("views at 128x64: read from their EXR files (the data set's width); simplified meshes: 0 read, "
                        "9 simplified") != std::string::npos);
  CHECK(std::filesystem::exists(directory / "selection.json"));
}

TEST_CASE("decimate at its defaults reads every view capture kept, and makes what is missing for the next run") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 512, 0);
  const Dataset dataset = Dataset::open(directory / "data");
  // What capture keeps as it writes each view.
  SelectionInputKeeper keeper(directory / "data", glm::ivec2(512, 256));
  for (int i = 0; i < dataset.sampleCount(); ++i) keeper.keep(dataset.sample(i), true, dataset.loadView(dataset.sample(i)));
  const std::string decimate = "decimate --quiet --target 5 --refine-radius 0 --dataset " + (directory / "data").string() +
                               " --out " + (directory / "selection.json").string();
  const RunResult kept = runTriwalk(directory, decimate);
  INFO("stderr: " << kept.err);
  REQUIRE(kept.status == 0);
  CHECK(kept.out.find("views at 256x128: 9 read from the data set's store, 0 downsampled from their EXR files; "
                      "simplified meshes: 9 read, 0 simplified") != std::string::npos);

  std::filesystem::remove_all(directory / "data" / "downsampled");
  std::filesystem::remove_all(directory / "data" / "meshes");
  const RunResult made = runTriwalk(directory, decimate);
  REQUIRE(made.status == 0);
  CHECK(made.out.find("0 read from the data set's store, 9 downsampled from their EXR files; simplified meshes: 0 "
                      "read, 9 simplified") != std::string::npos);
  const RunResult again = runTriwalk(directory, decimate);
  REQUIRE(again.status == 0);
  CHECK(again.out.find("9 read from the data set's store, 0 downsampled") != std::string::npos);
}

TEST_CASE("SIGTERM stops decimate and eval cleanly, with no partial output") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 12, 12, 256, 40);
  const std::string data = " --dataset " + (directory / "data").string();
  const std::filesystem::path selection = directory / "selection.json";
  const std::filesystem::path rows = directory / "rows.json";
  // Both commands run for tens of seconds on this data set; the signal
  // comes once the panoramas are loaded (their progress line shows), in
  // the middle of the work however loaded the machine is.
  const std::vector<std::string> commands = {
      "decimate" + data + " --target 4 --out " + selection.string(),
      "eval" + data + " --selection " + (directory / "small.json").string() + " --json " + rows.string(),
  };
  // eval needs a selection: a quick one.
  REQUIRE(runTriwalk(directory, "decimate --quiet --target 100 --refine-radius 0" + data + " --out " +
                                    (directory / "small.json").string())
              .status == 0);
  for (size_t k = 0; k < commands.size(); ++k) {
    const std::string& arguments = commands[k];
    CAPTURE(arguments);
    const std::filesystem::path status = directory / "status.txt";
    // A log of its own per command: with one shared file, the wait below
    // could read the previous command's load line before this one's
    // redirection emptied the file, and signal it before it started.
    const std::string log = (directory / ("log-" + std::to_string(k) + ".txt")).string();
    const std::string script = std::string(TRIWALK_BINARY) + " " + arguments + " > " + log +
                               " 2>&1 & pid=$!; for i in $(seq 600); do grep -q \"^load \" " + log +
                               " && break; sleep 0.1; done; kill -TERM $pid; wait $pid; echo $? > " + status.string();
    REQUIRE(std::system(("bash -c '" + script + "'").c_str()) == 0);
    const std::string printed = testing::readTextFileOrEmpty(log);
    INFO("log: " << printed);
    CHECK(printed.find("load 256x128:") != std::string::npos);
    CHECK(std::stoi(testing::readTextFileOrEmpty(status)) == 130);
    CHECK(printed.find("triwalk: interrupted; no output written") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(selection));
    CHECK_FALSE(std::filesystem::exists(rows));
    for (const auto& entry : std::filesystem::directory_iterator(directory.path())) {
      CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
    }
  }
}

TEST_CASE("SIGTERM stops capture while it searches an imported scene for its walkable region") {
  const std::filesystem::path house = "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc";
  REQUIRE_MESSAGE(std::filesystem::exists(house), "install assimp-testmodels (scripts/install-deps.sh test)");
  testing::TemporaryDirectory directory;
  const std::filesystem::path out = directory / "house", status = directory / "status.txt";
  // The flood fill probes about 1460 cells (about 6 s here); the signal
  // comes once its progress line shows (after the import, however long
  // that takes under the sanitizers).
  const std::string log = (directory / "log.txt").string();
  const std::string script = kTriwalkWithOpenGl + " capture --scene " + house.string() + " --out " + out.string() +
                             " --width 64 --probes 2 > " + log + " 2>&1 & pid=$!; for i in $(seq 600); do grep -q \"find walkable\" " +
                             log + " && break; sleep 0.1; done; kill -TERM $pid; wait $pid; echo $? > " + status.string();
  REQUIRE(std::system(("bash -c '" + script + "'").c_str()) == 0);
  const std::string printed = testing::readTextFileOrEmpty(log);
  INFO("log: " << printed);
  CHECK(printed.find("find walkable region: cells probed") != std::string::npos);
  CHECK(std::stoi(testing::readTextFileOrEmpty(status)) == 130);
  CHECK(printed.find("triwalk: interrupted; no output written") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
}

TEST_CASE("SIGTERM stops render cleanly: no frames, no statistics, no folder left behind") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 128, 0);
  const std::filesystem::path frames = directory / "frames", stats = directory / "stats.json", status = directory / "status.txt";
  const std::string log = (directory / "log.txt").string();
  // 400 frames take tens of seconds; the signal comes once some are written.
  const std::string script = kTriwalkWithOpenGl + " render --dataset " + (directory / "data").string() +
                             " --frames 400 --size 320x240 --out " + frames.string() + " --stats " + stats.string() +
                             " > " + log + " 2>&1 & pid=$!; for i in $(seq 600); do grep -q \"render: \" " + log +
                             " && break; sleep 0.1; done; sleep 1; kill -TERM $pid; wait $pid; echo $? > " + status.string();
  REQUIRE(std::system(("bash -c '" + script + "'").c_str()) == 0);
  const std::string printed = testing::readTextFileOrEmpty(log);
  INFO("log: " << printed);
  CHECK(std::stoi(testing::readTextFileOrEmpty(status)) == 130);
  CHECK(printed.find("triwalk: interrupted; no output written") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(frames));
  CHECK_FALSE(std::filesystem::exists(stats));
}

TEST_CASE("render --stats reports per frame the holes before the fill, none left after it, and the frame time") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 128, 0);
  // Behind the box at x 3..3.8, y -1.5..-0.9, outside the samples (y >= 0):
  // the wall and the box face it hides from every reference are holes.
  std::ofstream(directory / "path.txt") << "3.4 -1.8 1.5 270 -10\n3.4 -1.8 1.5 0 -10\n";
  const std::string common = "render --dataset " + (directory / "data").string() + " --path " +
                             (directory / "path.txt").string() + " --size 160x120 --out " + (directory / "frames").string();
  for (const std::string holes : {"fill", "mark"}) {
    const std::filesystem::path stats = directory / ("stats_" + holes + ".json");
    const RunResult run = runTriwalk(directory, common + " --holes " + holes + " --stats " + stats.string(), true);
    INFO(run.err);
    REQUIRE(run.status == 0);
    CHECK(run.out.find("(holes " + holes + ", reliability weights)") != std::string::npos);
    const nlohmann::json document = nlohmann::json::parse(testing::readTextFileOrEmpty(stats));
    CHECK(document["holes"] == holes);
    CHECK(document["blend_weights"] == "reliability");
    REQUIRE(document["frames"].size() == 2);
    for (size_t i = 0; i < 2; ++i) {
      const nlohmann::json& frame = document["frames"][i];
      CHECK(frame["frame"] == i);
      CHECK(frame["holes_before_fill"].get<double>() > 0.001);
      CHECK(frame["unfilled"].get<double>() == (holes == "fill" ? 0.0 : frame["holes_before_fill"].get<double>()));
      CHECK(frame["ms"].get<double>() > 0.0);
    }
  }
}

TEST_CASE("an irregular data set without paths decimates, evaluates against every baseline and renders") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 5, 4, 64, 6, 0.35f);
  const std::string data = " --dataset " + (directory / "data").string();
  const std::filesystem::path selection = directory / "selection.json", rows = directory / "rows.json";
  const RunResult decimate = runTriwalk(directory, "decimate --quiet --target 6" + data + " --out " + selection.string());
  INFO("decimate: " << decimate.err);
  REQUIRE(decimate.status == 0);
  const RunResult eval = runTriwalk(directory, "eval --quiet" + data + " --selection " + selection.string() + " --json " +
                                                   rows.string() + " --baselines-out " + (directory / "baselines").string());
  INFO("eval: " << eval.err);
  REQUIRE(eval.status == 0);
  std::vector<std::string> methods;
  const nlohmann::json document = nlohmann::json::parse(testing::readTextFileOrEmpty(rows));
  for (const nlohmann::json& row : document["rows"]) {
    methods.push_back(row["method"].get<std::string>());
    CHECK(row["probe_errors"].size() == 6);
    CHECK(row["samples"].get<int>() >= 3);
  }
  CHECK(methods == std::vector<std::string>{"initial", "uniform", "edge_collapse", "uniform_region", "kmedoids",
                                            "geodesic_kmedoids", "farthest_point", "random", "greedy_insertion",
                                            "insertion_refined"});
  // Greedy insertion's selections are written beside the baselines', and
  // every geometric baseline says how many views it needs for edge
  // collapse's probe mean.
  CHECK(std::filesystem::exists(directory / "baselines" / "insertion_refined.json"));
  CHECK(document["views_for_edge_collapse_error"].size() == 6);
  CHECK(eval.out.find("views each baseline needs for edge collapse's probe mean") != std::string::npos);
  // Every sample is a vertex of the dense triangulation; what edge collapse
  // leaves outside its triangles, decimate said too (or said nothing).
  CHECK(document["rows"][0]["samples_outside"].get<int>() == 0);
  const int outside = document["rows"][2]["samples_outside"].get<int>();
  const size_t said = decimate.out.find(" samples lie outside every view triangle");
  if (outside == 0) {
    CHECK(said == std::string::npos);
  } else {
    REQUIRE(said != std::string::npos);
    const size_t line = decimate.out.rfind('\n', said) + 1;
    CHECK(decimate.out.substr(line, said - line) == std::to_string(outside) + " of 20");
    CHECK(document["rows"][2]["farthest_outside_m"].get<double>() > 0.0);
  }
  // The selection prices its steps with the paper's inverse-distance
  // weights; the evaluation blends as the viewer does, by reliability.
  CHECK(decimate.out.find("distance weights") != std::string::npos);
  CHECK(eval.out.find("reliability weights") != std::string::npos);
  const nlohmann::json written = nlohmann::json::parse(testing::readTextFileOrEmpty(selection));
  CHECK(written["settings"]["blend_weights"] == "distance");
  CHECK_FALSE(written["settings"].contains("quality"));  // data only, no prose
  const RunResult render = runTriwalk(directory, "render" + data + " --selection " + selection.string() +
                                                     " --frames 2 --size 96x64 --out " + (directory / "frames").string(), true);
  INFO("render: " << render.err);
  REQUIRE(render.status == 0);
  CHECK(std::filesystem::exists(directory / "frames" / "frame_0000.png"));
  CHECK(std::filesystem::exists(directory / "frames" / "frame_0001.png"));

  // --baselines-out: each baseline an ordinary selection of the same count,
  // the very one eval judged (its probe errors again from the file).
  for (const char* method : {"uniform", "kmedoids", "uniform_region", "geodesic_kmedoids", "farthest_point", "random"}) {
    INFO(method);
    const std::filesystem::path file = directory / "baselines" / (std::string(method) + ".json");
    const Selection baseline = readSelection(file, Dataset::open(directory / "data"));
    CHECK(baseline.method == method);
    const nlohmann::json again = nlohmann::json::parse(testing::readTextFileOrEmpty(rows));
    for (const nlohmann::json& row : again["rows"]) {
      if (row["method"] == method) CHECK(int(baseline.samples.size()) == row["samples"].get<int>());
    }
  }
  const RunResult uniform = runTriwalk(directory, "eval --quiet" + data + " --selection " +
                                                      (directory / "baselines" / "uniform.json").string() + " --json " +
                                                      (directory / "uniform_rows.json").string());
  INFO("eval of the uniform file: " << uniform.err);
  REQUIRE(uniform.status == 0);
  const nlohmann::json judged = nlohmann::json::parse(testing::readTextFileOrEmpty(directory / "uniform_rows.json"));
  CHECK(judged["rows"][2]["probe_errors"] == document["rows"][1]["probe_errors"]);
}

TEST_CASE("suite: each count selected with the selection's blend weights and width, evaluated with the evaluation's") {
  testing::TemporaryDirectory directory;
  const std::filesystem::path out = directory / "suite";
  testing::writeAnalyticDataset(out / "room" / "dataset", 5, 4, 64, 6, 0.35f);  // found: no capture
  const std::filesystem::path spec = directory / "spec.json";
  writeTextFileAtomically(spec, R"({"format": "triwalk-suite", "width": 64, "probes": 6, "fractions": [0.3],
                                   "scenes": [{"name": "room", "scene": "builtin"}]})");
  auto run = [&](const std::string& options) {
    const RunResult result = runTriwalk(directory, "suite --quiet --spec " + spec.string() + " --out " + out.string() + options);
    INFO("suite: " << result.err);
    REQUIRE(result.status == 0);
    const nlohmann::json document = nlohmann::json::parse(testing::readTextFileOrEmpty(out / "suite.json"));
    REQUIRE(document["rows"].size() == 1);
    const nlohmann::json& row = document["rows"][0];
    CHECK(row["samples"].get<int>() == 6);
    CHECK(row["probe_errors"]["edge_collapse"].size() == 6);
    // Greedy insertion, alone and refined, at edge collapse's count, and the
    // views every method needs for edge collapse's probe mean.
    CHECK(row["probe_errors"]["greedy_insertion"].size() == 6);
    CHECK(row["probe_errors"]["insertion_refined"].size() == 6);
    CHECK(readSelection(out / "room" / "greedy_insertion_6.json", Dataset::open(out / "room" / "dataset")).samples.size() ==
          row["edge_collapse_samples"].get<size_t>());
    CHECK(row["views_for_edge_collapse_error"].size() == 8);
    CHECK(result.out.find("evaluation with errors at 64x32") != std::string::npos);
    const std::string evaluation = result.out.substr(result.out.find("evaluation with"));
    CHECK(evaluation.substr(0, evaluation.find('\n')).find("reliability weights") != std::string::npos);
    CHECK(evaluation.substr(0, evaluation.find('\n')).find("simplified") == std::string::npos);
    return row;
  };
  const nlohmann::json byDefault = run("");
  CHECK(byDefault["settings"]["blend_weights"] == "distance");
  const nlohmann::json reliability = run(" --selection-blend-weights reliability");
  CHECK(reliability["settings"]["blend_weights"] == "reliability");
  // The probes and the baselines are the same; only the selection differs.
  CHECK(reliability["probe_errors"]["uniform"] == byDefault["probe_errors"]["uniform"]);
  const Selection written = readSelection(out / "room" / "selection_6.json", Dataset::open(out / "room" / "dataset"));
  CHECK(written.settings["blend_weights"] == "reliability");
  // A coarser selection error: the selection says so, the evaluation stays at 64x32.
  const nlohmann::json coarse = run(" --selection-error-width 32");
  CHECK(coarse["settings"]["error_width"] == 32);
  CHECK(coarse["probe_errors"]["uniform"] == byDefault["probe_errors"]["uniform"]);
  // The selection warps simplified meshes unless asked for the grid: the
  // selection says which, the evaluation keeps the grid either way.
  CHECK(byDefault["settings"]["source_mesh"] == "simplified");
  CHECK(byDefault["settings"]["mesh_tolerance"] == 0.25);
  const nlohmann::json grid = run(" --selection-source-mesh grid");
  CHECK(grid["settings"]["source_mesh"] == "grid");
  CHECK(grid["probe_errors"]["uniform"] == byDefault["probe_errors"]["uniform"]);
  // Errors on a lattice for the selection alone: it says so, and the
  // evaluation still reads every pixel.
  const nlohmann::json lattice = run(" --error-stride 2");
  CHECK(lattice["settings"]["error_stride"].get<int>() == 2);
  CHECK(lattice["probe_errors"]["uniform"] == byDefault["probe_errors"]["uniform"]);
  // The paper's rules for the selection (as decimate --preset paper), the
  // evaluation unchanged; an option beside the preset overrides it.
  const nlohmann::json paper = run(" --preset paper");
  CHECK(paper["settings"]["preset"] == "paper");
  CHECK(paper["settings"]["cost"] == "centroid");
  CHECK(paper["settings"]["area_weighted_cost"] == false);
  CHECK(paper["settings"]["recosting"] == "eager");
  CHECK(paper["settings"]["refine_radius"] == 0.0);
  CHECK(paper["settings"]["pixel_weighting"] == "uniform");
  CHECK(byDefault["settings"]["pixel_weighting"] != "uniform");
  CHECK(byDefault["settings"]["preset"] == "default");
  CHECK(paper["probe_errors"]["uniform"] == byDefault["probe_errors"]["uniform"]);
  CHECK(paper["probe_errors"]["edge_collapse"] != byDefault["probe_errors"]["edge_collapse"]);
  const nlohmann::json paperReliability = run(" --preset paper --selection-blend-weights reliability");
  CHECK(paperReliability["settings"]["blend_weights"] == "reliability");
  CHECK(paperReliability["settings"]["cost"] == "centroid");

  // Tiles forced: each count selected in tiles and stitched, evaluated as before.
  const nlohmann::json tiled = run(" --tiles 2");
  CHECK(readSelection(out / "room" / "selection_6.json", Dataset::open(out / "room" / "dataset")).method ==
        "tiled_edge_collapse");
  CHECK(tiled["probe_errors"]["uniform"] == byDefault["probe_errors"]["uniform"]);
  CHECK(!std::filesystem::exists(out / "room" / "selection_6.json.tiles"));

  // A selection off its target (as when no valid collapse is left): the
  // baselines get as many references as edge collapse kept.
  REQUIRE(runTriwalk(directory, "decimate --quiet --dataset " + (out / "room" / "dataset").string() +
                                    " --target 9 --out " + (out / "room" / "selection_6.json").string())
              .status == 0);
  const RunResult offTarget =
      runTriwalk(directory, "suite --quiet --reuse-selections --spec " + spec.string() + " --out " + out.string());
  INFO("suite: " << offTarget.err);
  REQUIRE(offTarget.status == 0);
  CHECK(offTarget.out.find("| room | 9 (target 6) |") != std::string::npos);
  // Every table's rule has a column for each of its header's.
  std::istringstream lines(offTarget.out);
  std::string line, header;
  int tables = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("|---", 0) == 0) {
      ++tables;
      CHECK(std::count(line.begin(), line.end(), '|') == std::count(header.begin(), header.end(), '|'));
    }
    header = line;
  }
  CHECK(tables == 4);
  const nlohmann::json reused = nlohmann::json::parse(testing::readTextFileOrEmpty(out / "suite.json"))["rows"][0];
  CHECK(reused["samples"].get<int>() == 6);
  CHECK(reused["edge_collapse_samples"].get<int>() == 9);
  CHECK(reused["probe_errors"]["kmedoids"] != byDefault["probe_errors"]["kmedoids"]);
  // Greedy insertion follows edge collapse's new count.
  CHECK(readSelection(out / "room" / "greedy_insertion_6.json", Dataset::open(out / "room" / "dataset")).samples.size() == 9);
}

TEST_CASE("import and export from the command line: a round trip, its report, and bad options in one line") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 32, 1);
  const std::filesystem::path exported = directory / "realsee", imported = directory / "back";
  REQUIRE(runTriwalk(directory, "export --quiet --dataset " + (directory / "data").string() + " --to realsee --out " +
                                    exported.string()).status == 0);
  CHECK(std::filesystem::exists(exported / "viewpoints" / "p0" / "extrinsics.txt"));
  const RunResult run = runTriwalk(directory, "import --quiet --from realsee --in " + exported.string() + " --out " +
                                                  imported.string() + " --probes-fraction 0.2 --seed 3");
  INFO(run.err);
  REQUIRE(run.status == 0);
  CHECK(run.out.find("imported 8 samples and 2 probes of 32x16") != std::string::npos);
  CHECK(run.out.find("0 views resampled upright") != std::string::npos);
  const nlohmann::json manifest = nlohmann::json::parse(testing::readTextFileOrEmpty(imported / "manifest.json"));
  CHECK(manifest["capture"]["imported"]["layout"] == "realsee");
  CHECK(manifest["probes"].size() == 2);
  CHECK(run.out.find("replaces it") == std::string::npos);
  // Into the same folder again: the data set there is replaced, and said
  // so before the import begins.
  const RunResult again = runTriwalk(directory, "import --quiet --from realsee --in " + exported.string() + " --out " +
                                                    imported.string() + " --probes-fraction 0.2 --seed 3");
  REQUIRE(again.status == 0);
  const size_t said = again.out.find(imported.string() + " holds a data set of 8 samples");
  CHECK(said != std::string::npos);
  CHECK(again.out.find("this import replaces it once complete") != std::string::npos);
  CHECK(said < again.out.find("imported 8 samples"));

  for (const auto& [arguments, message] : std::vector<std::pair<std::string, std::string>>{
           {"import --from matterport --in " + exported.string() + " --out x", "--from"},
           {"import --from realsee --in " + (directory / "missing").string() + " --out x", "--in"},
           {"import --from realsee --in " + exported.string() + " --out x --depth-scale -1", "--depth-scale"},
           {"import --from realsee --in " + exported.string() + " --out x --depth-scale nan", "--depth-scale"},
           {"import --from realsee --in " + exported.string() + " --out x --probes-fraction 1.5", "--probes-fraction"},
           // The core names its setting (probes_fraction); the command line says the flag.
           {"import --from realsee --in " + exported.string() + " --out x --probes-fraction 0.8",
            "--probes-fraction: 10 views leave 2 samples; at least 3 are needed"},
           {"import --from realsee --in " + exported.string() + " --out x --up w", "--up"},
           {"import --from pano3d --in " + exported.string() + " --out x", "no pose file"},
           {"export --dataset " + (directory / "data").string() + " --to realsee --out " + exported.string(), "not empty"},
       }) {
    CAPTURE(arguments);
    const RunResult bad = runTriwalk(directory, arguments);
    CHECK(bad.status != 0);
    CHECK(bad.err.find(message) != std::string::npos);
    CHECK(std::count(bad.err.begin(), bad.err.end(), '\n') == 1);
    CHECK_FALSE(std::filesystem::exists(directory / "x"));
  }
}

}  // namespace triwalk

namespace triwalk {

TEST_CASE("help lists what a user needs, and --help-all the options that tune the method too") {
  testing::TemporaryDirectory directory;
  const RunResult help = runTriwalk(directory, "decimate --help");
  REQUIRE(help.status == 0);
  for (const char* everyday : {"--dataset", "--out", "--preset", "--relative-error", "--target", "--refine-radius",
                               "--error-stride", "--holes", "--help-all"}) {
    CHECK_MESSAGE(help.out.find(everyday) != std::string::npos, everyday);
  }
  for (const char* expert : {"--priced-samples", "--recosting", "--refine-screen", "--refine-priced", "--one-ring",
                             "--unweighted-cost", "--fixed-boundary", "--epsilon", "--alpha", "--grazing-angle"}) {
    CHECK_MESSAGE(help.out.find(expert) == std::string::npos, expert);
  }
  const RunResult all = runTriwalk(directory, "decimate --help-all");
  REQUIRE(all.status == 0);
  for (const char* expert : {"--priced-samples", "--recosting", "--refine-screen", "--epsilon", "--alpha"}) {
    CHECK_MESSAGE(all.out.find(expert) != std::string::npos, expert);
  }
  // The suite's options to select with other errors than it evaluates with.
  const RunResult suiteHelp = runTriwalk(directory, "suite --help");
  REQUIRE(suiteHelp.status == 0);
  CHECK(suiteHelp.out.find("--tiles") != std::string::npos);
  CHECK(suiteHelp.out.find("--selection-") == std::string::npos);
  CHECK(runTriwalk(directory, "suite --help-all").out.find("--selection-blend-weights") != std::string::npos);
  // Hidden from --help, not from the parser.
  testing::writeAnalyticDataset(directory / "data", 3, 3, 32, 0);
  const RunResult expertRun = runTriwalk(directory, "decimate --quiet --target 4 --priced-samples 4 --epsilon 0.06 --dataset " +
                                                        (directory / "data").string() + " --out " +
                                                        (directory / "s.json").string());
  INFO(expertRun.err);
  CHECK(expertRun.status == 0);
}

}  // namespace triwalk

namespace triwalk {

TEST_CASE("decimate --preset paper runs the paper's rules, as its options would, and options beside a preset override it") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 64, 1);
  const std::string dataset = " --dataset " + (directory / "data").string();
  auto decimate = [&](const std::string& options, const std::string& name) {
    const RunResult result = runTriwalk(directory, "decimate --quiet" + dataset + " " + options + " --out " +
                                                       (directory / name).string());
    INFO(options << ": " << result.err);
    REQUIRE(result.status == 0);
    return nlohmann::json::parse(readTextFile(directory / name));
  };
  nlohmann::json preset = decimate("--preset paper --target 5", "preset.json");
  const nlohmann::json& settings = preset["settings"];
  CHECK(settings["preset"] == "paper");
  CHECK(settings["cost"] == "centroid");
  CHECK(settings["fixed_boundary"] == true);
  CHECK(settings["area_weighted_cost"] == false);
  CHECK(settings["recosting"] == "eager");
  CHECK(settings["refine_radius"] == 0.0);
  CHECK(settings["exchanges"] == 0);
  CHECK(settings["point_warp"] == false);  // the mesh warp: the point warp is not the paper's splats
  CHECK(settings["blend_weights"] == "distance");
  CHECK(settings["holes"] == "black");
  CHECK(settings["pixel_weighting"] == "uniform");
  CHECK(settings["destinations"] == "centroid");
  CHECK(preset["collapses"].size() == 7);  // 12 samples to 5

  // The same run spelled out option by option: the same selection, every collapse included.
  nlohmann::json spelled = decimate("--target 5 --cost centroid --unweighted-cost --recosting eager --refine-radius 0 "
                                    "--exchanges 0 --blend-weights distance --holes black "
                                    "--pixel-weighting uniform --triangle-destinations centroid",
                                    "spelled.json");
  CHECK(spelled["settings"]["preset"] == "default");
  spelled["settings"].erase("preset");
  preset["settings"].erase("preset");
  CHECK(preset == spelled);

  // Without a stopping option the paper stops at its absolute 1.85; a stopping option replaces it.
  const nlohmann::json paperThreshold = decimate("--preset paper", "threshold.json");
  CHECK(paperThreshold["settings"]["max_error"] == kPaperMaxError);
  CHECK(paperThreshold["settings"]["relative_error"] == 0.0);
  const nlohmann::json relative = decimate("--preset paper --relative-error 1.5", "relative.json");
  CHECK(relative["settings"]["relative_error"] == 1.5);
  const nlohmann::json defaults = decimate("--refine-radius 0", "defaults.json");
  CHECK(defaults["settings"]["relative_error"] == kDefaultRelativeError);

  // An option beside the preset changes that setting alone.
  const nlohmann::json served = decimate("--preset paper --cost served-samples --target 5", "served.json");
  CHECK(served["settings"]["cost"] == "served-samples");
  CHECK(served["settings"]["pixel_weighting"] == "uniform");
  CHECK(decimate("--preset fast --target 5 --refine-radius 0", "fast.json")["settings"]["error_stride"] == 2);
  CHECK(decimate("--preset fast --error-stride 1 --target 5 --refine-radius 0", "exact.json")["settings"]["error_stride"] == 1);

  const RunResult unknown = runTriwalk(directory, "decimate --preset quick" + dataset + " --out " +
                                                      (directory / "unknown.json").string());
  CHECK(unknown.status != 0);
  CHECK(unknown.err.find("--preset") != std::string::npos);
  CHECK(std::count(unknown.err.begin(), unknown.err.end(), '\n') == 1);
  CHECK_FALSE(std::filesystem::exists(directory / "unknown.json"));
}

TEST_CASE("capture --scene builtin-floor:2x1 captures the floor's own region at three samples a metre") {
  testing::TemporaryDirectory directory;
  const RunResult run = runTriwalk(directory, "capture --quiet --scene builtin-floor:2x1 --width 16 --probes 4 --out " +
                                                  (directory / "floor").string(),
                                   true);
  INFO(run.err);
  REQUIRE(run.status == 0);
  CHECK(run.out.find("samples 0.33 m apart over a 52.1 m2 region") != std::string::npos);
  const Dataset floor = Dataset::open(directory / "floor");
  CHECK(floor.manifest().scene == "builtin-floor:2x1");
  CHECK(floor.sampleCount() == 480);
  CHECK(floor.probeCount() == 4);
  CHECK(floor.walkableRegion().area() == doctest::Approx(52.1).epsilon(0.01));
  // A density given on the command line wins over the floor's own.
  const RunResult sparse = runTriwalk(directory, "capture --quiet --scene builtin-floor:2x1 --width 16 --probes 0 --spacing 1 --out " +
                                                     (directory / "sparse").string(),
                                      true);
  REQUIRE(sparse.status == 0);
  CHECK(Dataset::open(directory / "sparse").sampleCount() < 80);
}

}  // namespace triwalk

namespace triwalk {

TEST_CASE("render warns in one line when its frames stand outside the walkable region, and synth refuses an --out it would not use and replaces its own as a whole") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 64, 1);
  const std::string data = " --dataset " + (directory / "data").string();
  const RunResult outside =
      runTriwalk(directory, "render" + data + " --frames 2 --size 64x48 --at 50,2.5 --out " + (directory / "far").string(), true);
  INFO(outside.err);
  CHECK(outside.status == 0);
  CHECK(outside.err.find("triwalk: warning: 2 of 2 frames stand outside the walkable region of ") != std::string::npos);
  const RunResult inside = runTriwalk(directory, "render" + data + " --frames 2 --size 64x48 --out " + (directory / "near").string(), true);
  CHECK(inside.status == 0);
  CHECK(inside.err.find("warning") == std::string::npos);

  const RunResult synth = runTriwalk(directory, "synth" + data + " --all-probes --out " + (directory / "images").string());
  CHECK(synth.status != 0);
  CHECK(synth.err.find("--out excludes --all-probes") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(directory / "images"));

  // synth's --out is replaced as a whole: its images, again, and nothing of an earlier run; a folder of other files is refused.
  const std::string reconstruct = "synth" + data + " --refs 0,1,3 --truth 4 --out " + (directory / "images").string();
  REQUIRE(runTriwalk(directory, reconstruct).status == 0);
  writeTextFileAtomically(directory / "images" / "stale.txt", "an earlier run's\n");
  REQUIRE(runTriwalk(directory, reconstruct).status == 0);
  std::vector<std::string> images;
  for (const auto& entry : std::filesystem::directory_iterator(directory / "images")) images.push_back(entry.path().filename().string());
  std::sort(images.begin(), images.end());
  CHECK(images == std::vector<std::string>{"heatmap.png", "reconstruction.png", "truth.png"});
  std::filesystem::create_directories(directory / "notes");
  writeTextFileAtomically(directory / "notes" / "mine.txt", "keep\n");
  const RunResult foreign = runTriwalk(directory, "synth" + data + " --refs 0,1,3 --truth 4 --out " + (directory / "notes").string());
  CHECK(foreign.status != 0);
  CHECK(std::count(foreign.err.begin(), foreign.err.end(), '\n') == 1);
  CHECK(std::filesystem::exists(directory / "notes" / "mine.txt"));
}


TEST_CASE("render --truth: from a sample's own position with every sample, frames match the scene to 30 dB, and a data set without its scene is refused first") {
  testing::TemporaryDirectory directory;
  const std::filesystem::path data = directory / "data";
  // Panoramas of 2048 pixels hold 5.7 pixels a degree, frames of 180 rows
  // over 60 degrees ask for 3: from a sample's own position the warp is
  // then near exact and what is left is filtering. (At 1024 the panorama
  // is the blurrier of the two and textured walls fall to 28 dB.)
  const RunResult capture = runTriwalk(directory, "capture --quiet --width 2048 --paths 3 --per-path 3 --probes 0 --out " +
                                                      data.string(), true);
  INFO(capture.err);
  REQUIRE(capture.status == 0);
  const Dataset dataset = Dataset::open(data);
  REQUIRE(dataset.manifest().capture.contains("scene"));
  const glm::vec3 middle = dataset.sample(4).position;
  const std::filesystem::path frames = directory / "frames", stats = directory / "stats.json";
  const RunResult render = runTriwalk(directory, "render --truth --dataset " + data.string() + " --at " +
                                                     std::to_string(middle.x) + "," + std::to_string(middle.y) +
                                                     " --frames 4 --size 320x180 --out " + frames.string() + " --stats " +
                                                     stats.string(), true);
  INFO(render.err);
  REQUIRE(render.status == 0);
  CHECK(render.out.find("frames against the scene: mean PSNR") != std::string::npos);
  const nlohmann::json document = nlohmann::json::parse(testing::readTextFileOrEmpty(stats));
  REQUIRE(document["frames"].size() == 4);
  for (const nlohmann::json& frame : document["frames"]) {
    INFO("frame " << frame.dump());
    CHECK(frame["psnr_truth"].get<double>() >= 30.0);
    CHECK(frame["ssim_truth"].get<double>() > 0.8);
    CHECK(frame["ssim_truth"].get<double>() < 1.0);
  }
  CHECK(document["truth"]["worst_psnr"].get<double>() >= 30.0);
  for (const char* name : {"frame_0003.png", "frame_0003_truth.png", "frame_0003_truth_diff.png"}) {
    CHECK(std::filesystem::exists(frames / name));
  }

  // Far from every sample the warp no longer matches the scene so well.
  const RunResult away = runTriwalk(directory, "render --truth --dataset " + data.string() +
                                                   " --at 9.5,4.5 --frames 4 --size 320x180 --out " +
                                                   (directory / "away").string() + " --stats " +
                                                   (directory / "away.json").string(), true);
  REQUIRE(away.status == 0);
  const nlohmann::json far = nlohmann::json::parse(testing::readTextFileOrEmpty(directory / "away.json"));
  CHECK(far["truth"]["mean_psnr"].get<double>() < document["truth"]["mean_psnr"].get<double>() - 1.0);

  // A data set that keeps no scene: one line naming its manifest, no frames.
  testing::writeAnalyticDataset(directory / "analytic", 3, 3, 64, 0);
  const RunResult refused = runTriwalk(directory, "render --truth --dataset " + (directory / "analytic").string() +
                                                      " --frames 2 --size 64x48 --out " + (directory / "none").string(), true);
  CHECK(refused.status != 0);
  CHECK(refused.err.find("manifest.json") != std::string::npos);
  CHECK(refused.err.find("keeps no scene to render the truth from") != std::string::npos);
  CHECK(std::count(refused.err.begin(), refused.err.end(), '\n') == 1);
  CHECK_FALSE(std::filesystem::exists(directory / "none"));
}


TEST_CASE("render --video encodes every frame at the asked rate into a file that decodes, and refuses an odd size or an unknown container before any frame") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 128, 0);
  const std::string render = "render --dataset " + (directory / "data").string() + " --frames 12 --size 160x96";
  const std::filesystem::path videos = directory / "videos";
  std::filesystem::create_directories(videos);
  const RunResult run = runTriwalk(directory, render + " --fps 24 --video " + (videos / "walk.mp4").string(), true);
  INFO(run.err);
  REQUIRE(run.status == 0);
  const VideoInfo info = readVideoInfo(videos / "walk.mp4");
  CHECK(info.frames == 12);
  CHECK(info.width == 160);
  CHECK(info.height == 96);
  CHECK(info.seconds == doctest::Approx(0.5).epsilon(0.01));  // 12 frames of 1/24 s, the last one too
  CHECK(run.out.find("wrote " + (videos / "walk.mp4").string() + ": 12 frames of 160x96 at 24 a second") != std::string::npos);
  // With --out too: the frames and the video.
  REQUIRE(runTriwalk(directory, render + " --out " + (directory / "frames").string() + " --video " +
                                    (videos / "both.mkv").string(), true).status == 0);
  CHECK(std::filesystem::exists(directory / "frames" / "frame_0011.png"));
  CHECK(readVideoInfo(videos / "both.mkv").frames == 12);
  // Side outputs inside --out, which does not exist yet, are part of it.
  const RunResult inside = runTriwalk(directory, render + " --out " + (directory / "run" / "out").string() + " --video " +
                                                     (directory / "run" / "out" / "walk.mp4").string() + " --stats " +
                                                     (directory / "run" / "out" / "stats.json").string(), true);
  INFO(inside.err);
  REQUIRE(inside.status == 0);
  CHECK(readVideoInfo(directory / "run" / "out" / "walk.mp4").frames == 12);
  CHECK(std::filesystem::exists(directory / "run" / "out" / "stats.json"));
  CHECK(std::filesystem::exists(directory / "run" / "out" / "frame_0011.png"));
  // Elsewhere, their folder must exist: refused before any frame.
  const RunResult nowhere = runTriwalk(directory, render + " --out " + (directory / "run2").string() + " --stats " +
                                                      (directory / "missing" / "stats.json").string(), true);
  CHECK(nowhere.status != 0);
  CHECK(nowhere.err.find("--stats: cannot write") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(directory / "run2"));

  // Refused before any frame, and nothing left behind.
  const RunResult odd = runTriwalk(directory, "render --dataset " + (directory / "data").string() +
                                                  " --frames 12 --size 161x96 --video " + (videos / "odd.mp4").string(), true);
  CHECK(odd.status != 0);
  CHECK(odd.err.find("odd.mp4: a video needs an even width and height, got 161x96") != std::string::npos);
  const RunResult unknown = runTriwalk(directory, render + " --video " + (videos / "walk.xyz").string(), true);
  CHECK(unknown.status != 0);
  CHECK(unknown.err.find("walk.xyz: no video container for its extension") != std::string::npos);
  const RunResult neither = runTriwalk(directory, render, true);
  CHECK(neither.status != 0);
  CHECK(neither.err.find("--out: give a directory for the frames, or --video FILE") != std::string::npos);
  std::vector<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(videos)) left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  CHECK(left == std::vector<std::string>{"both.mkv", "walk.mp4"});
}

}  // namespace triwalk
