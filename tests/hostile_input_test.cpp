// Issue 67's hostile user, case by case: numbers no computation can use,
// full disks, two writers on one output, files that never end, integers
// past 32 bits, counts of nothing, baselines that cannot be built and
// symlinks out of an imported folder. Each case fails without its fix:
// a crash, a partial or mixed output, or a run that never ends.

#include "core/io/dataset.h"
#include "tests/analytic_scene.h"
#include "tests/command_line_runner.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <sys/mount.h>
#include <sys/stat.h>

#include <algorithm>
#include <functional>
#include <fstream>
#include <string>
#include <vector>

namespace triwalk {

namespace {

using testing::RunResult;
using testing::runTriwalk;

bool isOneLineError(const RunResult& run) {
  return run.status != 0 && std::count(run.err.begin(), run.err.end(), '\n') == 1 && run.err.starts_with("triwalk: error: ");
}

void editManifest(const std::filesystem::path& dataset, const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json manifest = nlohmann::json::parse(testing::readTextFileOrEmpty(dataset / kManifestFileName));
  edit(manifest);
  std::ofstream(dataset / kManifestFileName) << manifest.dump(1);
}

// A folder on a filesystem of `bytes`: a tmpfs where this process may mount
// (root, as CI runs), unmounted by the destructor.
class SmallFilesystem {
public:
  SmallFilesystem(const std::filesystem::path& folder, size_t bytes) : folder_(folder) {
    std::filesystem::create_directories(folder);
    mounted_ = ::mount("tmpfs", folder.c_str(), "tmpfs", 0, ("size=" + std::to_string(bytes)).c_str()) == 0;
  }
  ~SmallFilesystem() {
    if (mounted_) ::umount(folder_.c_str());
  }
  SmallFilesystem(const SmallFilesystem&) = delete;
  SmallFilesystem& operator=(const SmallFilesystem&) = delete;
  bool mounted() const { return mounted_; }

private:
  std::filesystem::path folder_;
  bool mounted_ = false;
};

}  // namespace

TEST_CASE("numbers no computation can use are refused where they enter, in one line") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 32, 2);
  const std::string data = " --dataset " + (directory / "data").string();
  const std::string out = (directory / "out").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      // An empty blend interval or a weight that underflows made every blended pixel NaN,
      // which indexed the sRGB table far outside it (a segmentation fault).
      {"decimate" + data + " --out " + out + " --epsilon 0", "--epsilon: must be from 0.0001 to 10, got 0"},
      {"eval" + data + " --selection " + out + " --epsilon 0", "--epsilon: must be from 0.0001 to 10, got 0"},
      {"decimate" + data + " --out " + out + " --min-weight-distance 1e308", "--min-weight-distance: must be from 0.001"},
      {"decimate" + data + " --out " + out + " --alpha 1e300", "--alpha: must be from 0 to 1e+06"},
      {"decimate" + data + " --out " + out + " --relative-error 1e300", "--relative-error: must be from 1e-06 to 1e+06"},
      {"capture --out " + out + " --area 0,0,1e30,1e30", "--area: must be within 100 km (1e5 m) of the origin, got 1e30"},
      {"render" + data + " --out " + out + " --at 1e30,0", "--at: must be within 100 km"},
      {"render" + data + " --out " + out + " --frames 0", "--frames: Value 0 not in range 1"},
      {"render" + data + " --out " + out + " --frames -1", "--frames: Value -1 not in range 1"},
      {"capture --out " + out + " --face-size -1", "--face-size: Value -1 not in range 0"},
      {"capture --out " + out + " --width 1000000000", "--width: Value 1000000000 not in range 16 to 32768"},
      // Requests that grew to gigabytes with no output, deaf to Ctrl-C.
      {"capture --out " + out + " --probes 1000000000", "--probes: Value 1000000000 not in range 0 to 10000000"},
      {"capture --out " + out + " --paths 100000 --per-path 100000", "--paths/--per-path: gives 1e+10 samples"},
      {"capture --out " + out + " --spacing 0.001", "--spacing: gives 5e+07 samples"},
      {"capture --out " + out + " --spacing 1e-9", "--spacing: gives 5e+19 samples"},
      // A million views at 4096 x 2048 need about 31 TiB: refused before the first is rendered.
      {"capture --out " + out + " --width 4096 --probes 1000000", "1000450 views at 4096x2048 need about 31264.1 GiB on disk"},
  };
  for (const auto& [arguments, message] : cases) {
    CAPTURE(arguments);
    const RunResult run = runTriwalk(directory, arguments, true);
    INFO("stderr: " << run.err);
    CHECK(isOneLineError(run));
    CHECK(run.err.find(message) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
  }

  // The same numbers in a data set: a sample or a probe at x = 1e30 warped to NaN.
  for (const std::string kind : {"samples", "probes"}) {
    const std::filesystem::path far = directory / ("far_" + kind);
    std::filesystem::copy(directory / "data", far, std::filesystem::copy_options::recursive);
    editManifest(far, [&](nlohmann::json& manifest) { manifest[kind][1]["position"][0] = 1e30; });
    const RunResult run = runTriwalk(directory, "decimate --dataset " + far.string() + " --out " + out);
    INFO("stderr: " << run.err);
    CHECK(isOneLineError(run));
    CHECK(run.err.find("manifest.json: " + kind.substr(0, kind.size() - 1) + " 1: position (1e+30, ") != std::string::npos);
    CHECK(run.err.find("is farther than 100 km (1e5 m) from the origin") != std::string::npos);
  }
}

TEST_CASE("JSON integers are read at full width: an id past 32 bits is refused, not wrapped") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 32, 1);
  const std::filesystem::path wide = directory / "wide";
  std::filesystem::copy(directory / "data", wide, std::filesystem::copy_options::recursive);
  // 4294967301 is 2^32 + 5: read as 32 bits it was id 5, "appears twice".
  editManifest(wide, [](nlohmann::json& manifest) { manifest["samples"][0]["id"] = 4294967301ULL; });
  RunResult run = runTriwalk(directory, "decimate --dataset " + wide.string() + " --out " + (directory / "s.json").string());
  INFO("stderr: " << run.err);
  CHECK(isOneLineError(run));
  CHECK(run.err.find("field 'samples[0].id' 4294967301 is out of range") != std::string::npos);

  REQUIRE(runTriwalk(directory, "decimate --quiet --target 4 --dataset " + (directory / "data").string() + " --out " +
                                    (directory / "s.json").string()).status == 0);
  nlohmann::json selection = nlohmann::json::parse(testing::readTextFileOrEmpty(directory / "s.json"));
  selection["samples"][0] = 2147483648LL;  // 2^31: read as 32 bits it was negative
  std::ofstream(directory / "wide.json") << selection.dump();
  run = runTriwalk(directory, "eval --dataset " + (directory / "data").string() + " --selection " +
                                  (directory / "wide.json").string());
  CHECK(isOneLineError(run));
  CHECK(run.err.find("samples[0]: sample id 2147483648 is out of range") != std::string::npos);
}

TEST_CASE("only regular files of a bounded size are read: no endless read of /dev/zero, no wait on a FIFO") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 32, 1);
  const std::filesystem::path manifest = directory / "data" / kManifestFileName;
  std::filesystem::rename(manifest, directory / "manifest.saved");
  std::filesystem::create_symlink("/dev/zero", manifest);
  // Without the check this read 9 GB before failing; `timeout` ends the FIFO's wait if it comes back.
  RunResult run = runTriwalk(directory, "eval --dataset " + (directory / "data").string() + " --selection x.json");
  CHECK(isOneLineError(run));
  CHECK(run.err.find("manifest.json: is not a regular file") != std::string::npos);

  std::filesystem::remove(manifest);
  REQUIRE(::mkfifo(manifest.c_str(), 0600) == 0);
  const std::string command = "timeout 20 " + std::string(TRIWALK_BINARY) + " eval --dataset " +
                              (directory / "data").string() + " --selection x.json 2> " + (directory / "err.txt").string();
  const int status = std::system(command.c_str());
  CHECK(WEXITSTATUS(status) == 1);  // timeout's 124 if it waited
  CHECK(testing::readTextFileOrEmpty(directory / "err.txt").find("manifest.json: is not a regular file") != std::string::npos);

  std::filesystem::remove(manifest);
  std::filesystem::rename(directory / "manifest.saved", manifest);
  {
    std::ofstream huge(directory / "huge.json");
    huge.seekp((std::streamoff(256) << 20) + 1);
    huge << ' ';
  }
  run = runTriwalk(directory, "eval --dataset " + (directory / "data").string() + " --selection " +
                                  (directory / "huge.json").string());
  CHECK(isOneLineError(run));
  CHECK(run.err.find("huge.json: is 256 MiB; triwalk reads such files up to 256 MiB") != std::string::npos);
}

TEST_CASE("error lines print the bytes of a corrupt input escaped and cut short") {
  testing::TemporaryDirectory directory;
  std::ofstream(directory / "path.txt", std::ios::binary) << std::string("1 2 \x01\x02\xff\x1b[31m") + std::string(2000, 'x');
  testing::writeAnalyticDataset(directory / "data", 3, 3, 32, 0);
  const RunResult run = runTriwalk(directory, "render --dataset " + (directory / "data").string() + " --path " +
                                                  (directory / "path.txt").string() + " --out " + (directory / "f").string());
  INFO("stderr: " << run.err);
  CHECK(isOneLineError(run));
  CHECK(run.err.find("\\x01\\x02\\xff\\x1b[31m") != std::string::npos);
  CHECK(run.err.size() < 500);
  CHECK(std::none_of(run.err.begin(), run.err.end() - 1, [](char c) { return c < 0x20 || c == 0x7f; }));
}

TEST_CASE("eval evaluates what it can and names a baseline it cannot build at the selection's count") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 32, 2);
  const std::string data = " --dataset " + (directory / "data").string();
  const std::string selection = (directory / "s.json").string();
  REQUIRE(runTriwalk(directory, "decimate --quiet --target 3" + data + " --out " + selection).status == 0);
  // k-medoids of 3 on a 3 x 3 lattice are the middle row: collinear, no triangle.
  const RunResult run = runTriwalk(directory, "eval --quiet" + data + " --selection " + selection + " --json " +
                                                  (directory / "rows.json").string());
  INFO("stderr: " << run.err);
  REQUIRE(run.status == 0);
  CHECK(run.out.find("| k-medoids | not built at 3 samples: the sample positions are collinear") != std::string::npos);
  CHECK(run.out.find("| edge collapse (c) | 3 | 1 |") != std::string::npos);
  CHECK(run.out.find("  uniform (b) ") != std::string::npos);
  const nlohmann::json rows = nlohmann::json::parse(testing::readTextFileOrEmpty(directory / "rows.json"));
  CHECK(rows["not_built"].contains("kmedoids"));
  // initial, edge collapse, six baselines and greedy insertion alone and refined
  CHECK(rows["rows"].size() + rows["not_built"].size() == 10);
}

TEST_CASE("import follows no symlink out of --in, as the data set reader follows none out of its folder") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 32, 0);
  const std::filesystem::path exported = directory / "folder";
  REQUIRE(runTriwalk(directory, "export --quiet --dataset " + (directory / "data").string() + " --to folder --out " +
                                    exported.string()).status == 0);
  std::filesystem::path color;
  for (const auto& entry : std::filesystem::directory_iterator(exported / "color")) color = entry.path();
  REQUIRE_FALSE(color.empty());
  std::filesystem::rename(color, directory / "outside.png");
  std::filesystem::create_symlink(directory / "outside.png", color);
  const std::string import = "import --quiet --from folder --in " + exported.string() + " --out " +
                             (directory / "imported").string();
  RunResult run = runTriwalk(directory, import);
  INFO("stderr: " << run.err);
  CHECK(isOneLineError(run));
  CHECK(run.err.find("leads outside " + exported.string() + " (symlink)") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(directory / "imported"));

  // A pose no computation can use is refused before any view is converted.
  std::filesystem::remove(color);
  std::filesystem::rename(directory / "outside.png", color);
  std::string poses = testing::readTextFileOrEmpty(exported / "poses.csv");
  const size_t x = poses.find(',', poses.find('\n') + 1) + 1;  // the first view's x
  poses.replace(x, poses.find(',', x) - x, "1e30");
  std::ofstream(exported / "poses.csv") << poses;
  run = runTriwalk(directory, import);
  INFO("poses: " << poses << "\nstderr: " << run.err);
  CHECK(isOneLineError(run));
  CHECK(run.err.find("is farther than 100 km (1e5 m) from the origin") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(directory / "imported"));
}

TEST_CASE("render replaces its output folder as a whole: no frame of an earlier run stays, no other folder is taken") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 64, 0);
  const std::string render = "render --size 64x48 --dataset " + (directory / "data").string() + " --out " +
                             (directory / "frames").string();
  REQUIRE(runTriwalk(directory, render + " --frames 10", true).status == 0);
  CHECK(testing::countEntries(directory / "frames", "frame_") == 10);
  const RunResult again = runTriwalk(directory, render + " --frames 3", true);
  INFO("stderr: " << again.err);
  REQUIRE(again.status == 0);
  CHECK(testing::countEntries(directory / "frames", "frame_") == 3);
  CHECK(testing::countEntries(directory.path(), ".frames.triwalk-lock") == 0);
  CHECK(testing::countEntries(directory.path(), "frames.partial-triwalk") == 0);

  std::filesystem::create_directories(directory / "mine");
  std::ofstream(directory / "mine" / "notes.txt") << "keep\n";
  const RunResult refused = runTriwalk(directory, "render --size 64x48 --frames 2 --dataset " +
                                                      (directory / "data").string() + " --out " + (directory / "mine").string(),
                                       true);
  CHECK(isOneLineError(refused));
  CHECK(refused.err.find("mine: exists and is not an earlier render; refusing to overwrite it") != std::string::npos);
  CHECK(testing::countEntries(directory / "mine", "") == 1);
}

TEST_CASE("a file output is replaced only when it is absent, empty or this kind's own: another command's file or a user's is refused") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 64, 4);
  const std::string data = " --dataset " + (directory / "data").string();
  const std::string decimate = "decimate --quiet --target 4 --refine-radius 0" + data + " --out ";
  const std::filesystem::path manifest = directory / "data" / "manifest.json", notes = directory / "notes.json",
                              selection = directory / "s.json", empty = directory / "empty.json";
  std::ofstream(notes) << R"({"mine": true})";
  std::ofstream(empty).flush();
  const std::string manifestBefore = testing::readTextFileOrEmpty(manifest);

  // A data set's manifest and a user's JSON are refused by the selection's writer, before any work, untouched.
  for (const std::filesystem::path& foreign : {manifest, notes}) {
    const std::string before = testing::readTextFileOrEmpty(foreign);
    const RunResult refused = runTriwalk(directory, decimate + foreign.string());
    INFO("stderr: " << refused.err);
    CHECK(isOneLineError(refused));
    CHECK(refused.err.find(foreign.string() + " exists and is not a triwalk selection; refusing to overwrite it") !=
          std::string::npos);
    CHECK(testing::readTextFileOrEmpty(foreign) == before);
  }
  CHECK(testing::readTextFileOrEmpty(manifest) == manifestBefore);

  // Its own earlier output and an empty file are replaced.
  REQUIRE(runTriwalk(directory, decimate + selection.string()).status == 0);
  REQUIRE(runTriwalk(directory, "decimate --quiet --target 5 --refine-radius 0" + data + " --out " + selection.string()).status == 0);
  CHECK(nlohmann::json::parse(testing::readTextFileOrEmpty(selection))["samples"].size() == 5);
  REQUIRE(runTriwalk(directory, decimate + empty.string()).status == 0);
  CHECK(nlohmann::json::parse(testing::readTextFileOrEmpty(empty))["format"] == "triwalk-selection");

  // The other file outputs: each refuses the selection, which is not its kind.
  const std::string selectionBefore = testing::readTextFileOrEmpty(selection);
  const std::vector<std::pair<std::string, std::string>> others = {
      {"eval --quiet" + data + " --selection " + selection.string() + " --json " + selection.string(),
       "not a triwalk evaluation (eval --json)"},
      {"render --size 32x24 --frames 1" + data + " --out " + (directory / "frames").string() + " --stats " + selection.string(),
       "not triwalk render statistics (render --stats)"},
      {"region" + data + " --out " + selection.string(), "not a PNG image"},
      {"render --size 32x24 --frames 1" + data + " --video " + selection.string(), "not a video (MP4, MOV or Matroska)"},
  };
  for (const auto& [command, problem] : others) {
    const RunResult refused = runTriwalk(directory, command, true);
    INFO(command << "\nstderr: " << refused.err);
    CHECK(isOneLineError(refused));
    CHECK(refused.err.find(selection.string() + " exists and is " + problem + "; refusing to overwrite it") != std::string::npos);
    CHECK(testing::readTextFileOrEmpty(selection) == selectionBefore);
  }
  CHECK_FALSE(std::filesystem::exists(directory / "frames"));

  // eval's own JSON is its to replace, and it says what it is.
  const std::string eval = "eval --quiet" + data + " --selection " + selection.string() + " --json " + (directory / "e.json").string();
  REQUIRE(runTriwalk(directory, eval).status == 0);
  REQUIRE(runTriwalk(directory, eval).status == 0);
  CHECK(nlohmann::json::parse(testing::readTextFileOrEmpty(directory / "e.json"))["format"] == "triwalk-evaluation");
  // So is one written before evaluations carried their format.
  const std::filesystem::path earlier = directory / "table1.json";
  std::ofstream(earlier) << R"({"dataset": "d", "not_built": {}, "rows": []})";
  REQUIRE(runTriwalk(directory, "eval --quiet" + data + " --selection " + selection.string() + " --json " + earlier.string()).status == 0);
  CHECK(nlohmann::json::parse(testing::readTextFileOrEmpty(earlier))["rows"].size() > 2);
}

TEST_CASE("a second writer of the same output is refused in one line while the first finishes whole") {
  testing::TemporaryDirectory directory;
  const std::filesystem::path capture = directory / "cap", status = directory / "status.txt";
  const std::string log = (directory / "first.txt").string();
  // The first capture takes seconds; the second starts once the first is staging its views.
  const std::string script = testing::kTriwalkWithOpenGl + " capture --quiet --out " + capture.string() +
                             " --width 512 --paths 6 --per-path 6 --probes 20 > " + log + " 2>&1 & pid=$!; " +
                             "for i in $(seq 600); do ls -d " + capture.string() +
                             ".partial-triwalk-* > /dev/null 2>&1 && break; sleep 0.05; done; " +
                             testing::kTriwalkWithOpenGl + " capture --quiet --out " + capture.string() +
                             " --width 128 --paths 6 --per-path 6 --probes 2 > /dev/null 2> " + (directory / "second.txt").string() +
                             "; echo $? > " + (directory / "second_status.txt").string() + "; wait $pid; echo $? > " +
                             status.string();
  REQUIRE(std::system(("bash -c '" + script + "'").c_str()) == 0);
  const std::string second = testing::readTextFileOrEmpty(directory / "second.txt");
  INFO("first: " << testing::readTextFileOrEmpty(log) << "\nsecond: " << second);
  CHECK(std::stoi(testing::readTextFileOrEmpty(directory / "second_status.txt")) == 1);
  CHECK(second.find("cap: another triwalk is writing this output (process ") != std::string::npos);
  CHECK(std::count(second.begin(), second.end(), '\n') == 1);
  CHECK(std::stoi(testing::readTextFileOrEmpty(status)) == 0);
  const Dataset dataset = Dataset::open(capture);
  CHECK(dataset.sampleCount() == 36);
  CHECK(dataset.probeCount() == 20);
  CHECK(dataset.manifest().width == 512);
  CHECK(testing::countEntries(directory.path(), "cap.partial") == 0);
  CHECK(testing::countEntries(directory.path(), ".cap.triwalk-lock") == 0);
}

TEST_CASE("a full disk fails render, export-png and region in one line and leaves no partial file") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 256, 1);
  const std::string data = " --dataset " + (directory / "data").string();
  const std::filesystem::path full = directory / "full";
  // 96 KiB: room for the staging folder and a frame or two, not for the whole output.
  const SmallFilesystem disk(full, 96 << 10);
  // Where this process may not mount, a file size limit makes the same
  // writes fail (EFBIG instead of ENOSPC; SIGXFSZ ignored so the write
  // returns its error as a full disk's does).
  const std::string prefix = disk.mounted() ? "" : "trap \"\" XFSZ; ulimit -f 48; ";
  MESSAGE(std::string(disk.mounted() ? "a 96 KiB tmpfs" : "no mount allowed here: a 48 KiB file size limit instead"));
  const std::vector<std::pair<std::string, std::string>> commands = {
      {"render" + data + " --size 640x480 --frames 6 --out " + (full / "frames").string(), "frame_"},
      {"export-png" + data + " --views all --out " + (full / "png").string(), ".png"},
      {"region" + data + " --size 3000 --out " + (full / "region.png").string(), "region.png"},
  };
  for (const auto& [arguments, written] : commands) {
    CAPTURE(arguments);
    const std::string command = prefix + testing::kTriwalkWithOpenGl + " " + arguments + " > " +
                                (directory / "out.txt").string() + " 2> " + (directory / "err.txt").string();
    const int status = std::system(("bash -c '" + command + "'").c_str());
    const std::string err = testing::readTextFileOrEmpty(directory / "err.txt");
    INFO("stderr: " << err);
    CHECK(WEXITSTATUS(status) == 1);
    // One error line, the last, after the progress line the failure ended.
    const std::string last = err.substr(err.rfind('\n', err.size() - 2) + 1);
    CHECK(last.starts_with("triwalk: error: "));
    CHECK(err.find("triwalk: error: ") == err.size() - last.size());
    CHECK((err.find("No space left on device") != std::string::npos || err.find("File too large") != std::string::npos));
    CHECK(err.find("partial-triwalk") == std::string::npos);  // names the output, not the staging folder
    // Nothing is left in the full folder: no frame, no staging folder, no temporary, no lock.
    CHECK(testing::countEntries(full, "") == 0);
  }
}

}  // namespace triwalk
