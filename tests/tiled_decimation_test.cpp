// Tiled decimation from the command line (issue 69): one small floor cut
// into 4 tiles, run every way a user can run it: the selection must be the
// same byte for byte, a killed tile is rerun alone, stitching refuses an
// incomplete set in one line, and the stitched selection respects the
// walls and serves every sample.

#include "core/io/dataset.h"
#include "core/io/json_fields.h"
#include "core/selection/selection.h"
#include "tests/command_line_runner.h"

#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <fstream>

namespace triwalk {
namespace {

using testing::RunResult;
using testing::readTextFileOrEmpty;
using testing::runTriwalk;

// The floor the tests tile: 3 x 1 rooms, 201 samples 0.6 m apart, 32
// pixels wide (errors at 32x16), captured once for every test case (the
// smallest that still makes 4 tiles of a few dozen samples: each whole
// tiled run is about 5 s here, 40 s under the sanitizers). Its
// 4 tiles lie in a row, so the seam pass runs in 2 rounds of 2 steps: the
// jobs can change the order the steps of a round run in.
const std::filesystem::path& floorDataset() {
  static testing::TemporaryDirectory directory;
  static const std::filesystem::path floor = [] {
    const std::filesystem::path path = directory / "floor";
    const RunResult run = runTriwalk(directory, "capture --quiet --scene builtin-floor:3x1 --width 32 --probes 4 --spacing 0.6 --out " +
                                                    path.string(),
                                     true);
    INFO(run.err);
    REQUIRE(run.status == 0);
    return path;
  }();
  return floor;
}

// mpirun as a cluster user runs it (as root here, which OpenMPI refuses
// unless told). OpenMPI's own allocations outlive MPI_Finalize, so under the
// sanitizers its ranks run without leak detection, as OpenGL runs do.
RunResult runUnderMpirun(const testing::TemporaryDirectory& scratch, int ranks, const std::string& arguments) {
  const std::filesystem::path out = scratch / "mpi_stdout.txt", err = scratch / "mpi_stderr.txt";
  const std::string root = geteuid() == 0 ? " --allow-run-as-root" : "";
  const std::string command = "ASAN_OPTIONS=\"$ASAN_OPTIONS:detect_leaks=0\" mpirun" + root + " --oversubscribe -np " +
                              std::to_string(ranks) + " " + TRIWALK_BINARY + " " + arguments + " > " + out.string() +
                              " 2> " + err.string();
  const int status = std::system(command.c_str());
  return {status, readTextFileOrEmpty(out), readTextFileOrEmpty(err)};
}

std::string bytesOf(const std::filesystem::path& path) { return readTextFileOrEmpty(path); }

}  // namespace

TEST_CASE("a tiled selection is the same byte for byte with --jobs 1, --jobs 2, tiles plan/run/stitch and mpirun -np 2") {
  testing::TemporaryDirectory directory;
  const std::string dataset = floorDataset().string();
  const std::filesystem::path one = directory / "jobs1.json";
  const RunResult single = runTriwalk(directory, "decimate --quiet --tiles 4 --jobs 1 --dataset " + dataset + " --out " + one.string());
  INFO(single.err);
  REQUIRE(single.status == 0);
  CHECK(single.out.find("the 4 tiles' cores kept") != std::string::npos);
  CHECK(single.out.find("the seam pass (2 rounds)") != std::string::npos);
  CHECK(!std::filesystem::exists(directory / "jobs1.json.tiles"));  // the work folder goes once the selection is written
  const std::string reference = bytesOf(one);
  const Dataset floor = Dataset::open(floorDataset());
  const Selection selection = readSelection(one, floor);
  CHECK(selection.method == "tiled_edge_collapse");
  CHECK(selection.samples.size() < size_t(floor.sampleCount()) / 2);  // decimated (one decimation keeps 85 of 201)

  const RunResult two = runTriwalk(directory, "decimate --quiet --tiles 4 --jobs 2 --dataset " + dataset + " --out " +
                                                  (directory / "jobs2.json").string());
  REQUIRE(two.status == 0);
  CHECK(bytesOf(directory / "jobs2.json") == reference);

  const std::string work = (directory / "work").string();
  REQUIRE(runTriwalk(directory, "tiles plan --quiet --tiles 4 --dataset " + dataset + " --out " + work).status == 0);
  for (int k = 0; k < 4; ++k) {
    REQUIRE(runTriwalk(directory, "tiles run --quiet --plan " + work + " --tile " + std::to_string(k)).status == 0);
  }
  REQUIRE(runTriwalk(directory, "tiles stitch --quiet --plan " + work + " --out " + (directory / "batch.json").string()).status == 0);
  CHECK(bytesOf(directory / "batch.json") == reference);

  const RunResult mpi = runUnderMpirun(directory, 2, "decimate --quiet --tiles 4 --dataset " + dataset + " --out " +
                                                         (directory / "mpi.json").string());
  INFO(mpi.err);
  REQUIRE(mpi.status == 0);
  CHECK(bytesOf(directory / "mpi.json") == reference);
}

TEST_CASE("a killed tile leaves no outcome: stitching refuses in one line naming it, and the tile rerun alone gives the same selection") {
  testing::TemporaryDirectory directory;
  const std::string dataset = floorDataset().string();
  REQUIRE(runTriwalk(directory, "decimate --quiet --tiles 4 --jobs 2 --dataset " + dataset + " --out " +
                                    (directory / "whole.json").string()).status == 0);
  const std::string work = (directory / "work").string();
  REQUIRE(runTriwalk(directory, "tiles plan --quiet --tiles 4 --dataset " + dataset + " --out " + work).status == 0);
  for (int k : {0, 1, 3}) REQUIRE(runTriwalk(directory, "tiles run --quiet --plan " + work + " --tile " + std::to_string(k)).status == 0);
  // Tile 2 takes most of a second (0.9 s here): killed a sixth of the way in.
  const std::string kill = "timeout -s KILL 0.15 " + std::string(TRIWALK_BINARY) + " tiles run --quiet --plan " + work + " --tile 2";
  const int killed = std::system(kill.c_str());
  REQUIRE(WIFEXITED(killed));
  REQUIRE(WEXITSTATUS(killed) == 137);
  CHECK(!std::filesystem::exists(directory / "work" / "tile_0002.json"));

  const RunResult refused = runTriwalk(directory, "tiles stitch --plan " + work + " --out " + (directory / "partial.json").string());
  CHECK(refused.status != 0);
  CHECK(refused.err == "triwalk: error: " + work + "/tile_0002.json: tile 2 of 4 has not run for this plan (run: triwalk "
                       "tiles run --plan " + work + " --tile 2)\n");
  CHECK(!std::filesystem::exists(directory / "partial.json"));

  REQUIRE(runTriwalk(directory, "tiles run --quiet --plan " + work + " --tile 2").status == 0);
  REQUIRE(runTriwalk(directory, "tiles stitch --quiet --plan " + work + " --out " + (directory / "stitched.json").string()).status == 0);
  CHECK(bytesOf(directory / "stitched.json") == bytesOf(directory / "whole.json"));

  // decimate itself goes on from the tiles a stopped run left in its work folder.
  const std::filesystem::path resumed = directory / "resumed.json";
  std::filesystem::create_directories(directory / "resumed.json.tiles");
  std::filesystem::copy(directory / "work", directory / "resumed.json.tiles", std::filesystem::copy_options::recursive);
  std::filesystem::remove(directory / "resumed.json.tiles" / "tile_0001.json");
  const RunResult going = runTriwalk(directory, "decimate --tiles 4 --jobs 1 --dataset " + dataset + " --out " + resumed.string());
  INFO(going.err);
  REQUIRE(going.status == 0);
  CHECK(going.out.find("going on with the tiles of") != std::string::npos);
  CHECK(going.out.find("3 of 4 tiles already run for this plan") != std::string::npos);
  CHECK(bytesOf(resumed) == bytesOf(directory / "whole.json"));
}

TEST_CASE("a stitched selection reaches its target exactly, keeps its view triangles inside the walls and serves every sample") {
  // 12, 20 and 30 of 201: the walls cut this floor's rooms, so some of a
  // tile's references lie in no triangle of the tile's own triangulation
  // (they stay references of the whole); at 12 no step can take out the
  // last one over the target, a reference in no view triangle, and it is
  // dropped.
  testing::TemporaryDirectory directory;
  const Dataset dataset = Dataset::open(floorDataset());
  const WalkableRegion region = dataset.walkableRegion();
  for (const int target : {12, 20, 30}) {
    CAPTURE(target);
    const std::filesystem::path out = directory / ("tiled_" + std::to_string(target) + ".json");
    const RunResult run = runTriwalk(directory, "decimate --tiles 4 --target " + std::to_string(target) + " --dataset " +
                                                    floorDataset().string() + " --out " + out.string());
    INFO(run.err);
    REQUIRE(run.status == 0);
    const Selection selection = readSelection(out, dataset);
    CHECK(selection.samples.size() == size_t(target));
    CHECK(run.out.find("kept " + std::to_string(target) + " of 201 samples") != std::string::npos);
    REQUIRE(!selection.triangles.empty());
    for (const Triangle& t : selection.triangles) {
      const glm::dvec2 a(dataset.sample(t[0]).position), b(dataset.sample(t[1]).position), c(dataset.sample(t[2]).position);
      CHECK(region.containsTriangle(a, b, c));
    }
    const ViewMesh mesh = selectionMesh(selection, dataset);
    for (int i = 0; i < dataset.sampleCount(); ++i) CHECK(mesh.locate(glm::dvec2(dataset.sample(i).position)) >= 0);
  }

  // Tiles whose cores meet no other (buildings apart) have empty bands, so
  // the seam pass cannot take out the cores' surplus: the cores' own pass
  // does. A band of 0 m makes every band empty.
  const std::string work = (directory / "apart").string();
  REQUIRE(runTriwalk(directory, "tiles plan --quiet --tiles 4 --target 20 --dataset " + floorDataset().string() +
                                    " --out " + work).status == 0);
  nlohmann::json plan = readJsonFile(directory / "apart" / "plan.json");
  plan["band"] = 0.0;
  writeJsonFile(directory / "apart" / "plan.json", plan);
  for (int k = 0; k < 4; ++k) {
    REQUIRE(runTriwalk(directory, "tiles run --quiet --plan " + work + " --tile " + std::to_string(k)).status == 0);
  }
  const RunResult stitched = runTriwalk(directory, "tiles stitch --plan " + work + " --out " + (directory / "apart.json").string());
  INFO(stitched.err);
  REQUIRE(stitched.status == 0);
  CHECK(stitched.out.find("the seam pass (1 rounds)") != std::string::npos);
  CHECK(stitched.out.find("the cores' pass took out ") != std::string::npos);
  CHECK(readSelection(directory / "apart.json", dataset).samples.size() == 20);
}

TEST_CASE("without a target, a tiled selection keeps as many references as its cores did, about what one decimation keeps") {
  testing::TemporaryDirectory directory;
  const std::string floor = floorDataset().string();
  const Dataset dataset = Dataset::open(floorDataset());
  REQUIRE(runTriwalk(directory, "decimate --quiet --tiles off --dataset " + floor + " --out " +
                                    (directory / "whole.json").string()).status == 0);
  const double whole = double(readSelection(directory / "whole.json", dataset).samples.size());

  // 85 of 201 in one decimation, 80 in the cores; a seam pass collapsing
  // its bands to the threshold again left 54.
  const std::filesystem::path tiled = directory / "tiled.json";
  const RunResult run = runTriwalk(directory, "decimate --tiles 4 --dataset " + floor + " --out " + tiled.string());
  INFO(run.err);
  REQUIRE(run.status == 0);
  const size_t kept = readSelection(tiled, dataset).samples.size();
  CHECK(run.out.find("the 4 tiles' cores kept " + std::to_string(kept) + ",") != std::string::npos);
  CHECK(run.out.find("made 0 collapses") != std::string::npos);
  CHECK(double(kept) >= 0.85 * whole);
  CHECK(double(kept) <= 1.15 * whole);
}

}  // namespace triwalk

namespace triwalk {

TEST_CASE("tiles refuses bad input in one line before any work: a bad --tiles, a tile not in the plan, a damaged plan, another plan's tile, a damaged tile") {
  testing::TemporaryDirectory directory;
  const std::string dataset = floorDataset().string();
  const RunResult badCount = runTriwalk(directory, "decimate --tiles many --dataset " + dataset + " --out " +
                                                       (directory / "x.json").string());
  CHECK(badCount.status != 0);
  CHECK(badCount.err.find("--tiles: must be auto, off or a number of tiles from 1 to 100000, got 'many'") != std::string::npos);

  const std::string work = (directory / "work").string();
  REQUIRE(runTriwalk(directory, "tiles plan --quiet --tiles 4 --dataset " + dataset + " --out " + work).status == 0);
  const RunResult outside = runTriwalk(directory, "tiles run --plan " + work + " --tile 4");
  CHECK(outside.status != 0);
  CHECK(outside.err == "triwalk: error: --tile: 4 is not a tile of " + work + " (0 to 3)\n");

  // A tile made for another plan is not stitched: it counts as not run.
  REQUIRE(runTriwalk(directory, "tiles run --quiet --plan " + work + " --tile 0").status == 0);
  const std::string other = (directory / "other").string();
  REQUIRE(runTriwalk(directory, "tiles plan --quiet --tiles 4 --relative-error 2 --dataset " + dataset + " --out " + other).status == 0);
  std::filesystem::copy_file(directory / "work" / "tile_0000.json", directory / "other" / "tile_0000.json");
  const RunResult stale = runTriwalk(directory, "tiles stitch --plan " + other + " --out " + (directory / "y.json").string());
  CHECK(stale.status != 0);
  CHECK(stale.err.find("tile_0000.json: tile 0 of 4 has not run for this plan") != std::string::npos);

  // A tile's file with counts no run makes: refused naming it.
  nlohmann::json negative = readJsonFile(directory / "work" / "tile_0000.json");
  negative["collapses"] = -1;
  writeJsonFile(directory / "work" / "tile_0000.json", negative);
  const RunResult counted = runTriwalk(directory, "tiles stitch --plan " + work + " --out " + (directory / "n.json").string());
  CHECK(counted.status != 0);
  CHECK(counted.err == "triwalk: error: " + work + "/tile_0000.json: collapses, moves and seconds must not be negative\n");

  // A plan whose tile could not be decimated (2 samples) or asks for a
  // negative count: refused naming the plan and the tile, before its views
  // are read.
  const nlohmann::json sound = readJsonFile(directory / "other" / "plan.json");
  for (const auto& [field, problem] : {std::pair{"samples", "samples: a tile needs at least 3, got 2"},
                                       std::pair{"target", "target must not be negative, got -1"}}) {
    nlohmann::json hostile = sound;
    nlohmann::json& tile = hostile["tiles"][1];
    if (std::string(field) == "samples") {
      tile["samples"] = nlohmann::json::array({tile["members"][0], tile["members"][1]});
    } else {
      tile["target"] = -1;
    }
    writeJsonFile(directory / "other" / "plan.json", hostile);
    const RunResult refused = runTriwalk(directory, "tiles run --plan " + other + " --tile 1");
    CHECK(refused.status != 0);
    CHECK(refused.err.rfind("triwalk: error: " + other + "/plan.json: ", 0) == 0);
    CHECK(refused.err.find(problem) != std::string::npos);
    CHECK(refused.err.find("load") == std::string::npos);
    CHECK(std::count(refused.err.begin(), refused.err.end(), '\n') == 1);
  }

  // A damaged plan: one line naming it, for every command that reads it.
  {
    std::ofstream damaged(directory / "work" / "plan.json");
    damaged << "{\"format\": \"triwalk-tile-plan\", \"version\": 1, \"tiles\": [";
  }
  for (const std::string& command : {"tiles run --plan " + work + " --tile 0",
                                     "tiles stitch --plan " + work + " --out " + (directory / "z.json").string()}) {
    const RunResult damaged = runTriwalk(directory, command);
    CHECK(damaged.status != 0);
    CHECK(damaged.err.rfind("triwalk: error: " + work + "/plan.json: ", 0) == 0);
    CHECK(std::count(damaged.err.begin(), damaged.err.end(), '\n') == 1);
  }
  CHECK(!std::filesystem::exists(directory / "z.json"));
}

}  // namespace triwalk
