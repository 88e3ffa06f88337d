// The viewer, run as a person would start it, under a virtual X server
// (xvfb-run): a few frames of a small data set, then its screenshot must
// show the walkthrough and the panels; its live decimation's errors.

#include "app/video/video_file.h"
#include "core/io/atomic_file.h"
#include "core/io/camera_path_file.h"
#include "core/io/dataset.h"
#include "core/io/png_io.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <sstream>

namespace triwalk {

namespace {

struct ViewerRun {
  int status;
  std::string log;
};

// `triwalk <arguments>` with stdout and stderr in one log; under a
// virtual X server unless without a display. The viewer's preferences live
// in the scratch folder, never in the home of whoever runs the tests.
ViewerRun runTriwalk(const testing::TemporaryDirectory& scratch, const std::string& arguments, bool display = true) {
  const std::filesystem::path log = scratch / "log.txt";
  const std::string command = "XDG_CONFIG_HOME=" + (scratch / "config").string() + " " +
                              std::string(display ? "xvfb-run -a -s '-screen 0 1280x800x24' " : "") + TRIWALK_BINARY +
                              " " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  return {status, testing::readTextFileOrEmpty(log)};
}

// Distinct colours in a rectangle of the image: the scene's smooth shading
// gives hundreds, a clear colour or a panel's flat fill a few.
size_t distinctColours(const Rgb8Image& image, int x0, int y0, int x1, int y1) {
  std::set<uint32_t> colours;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const glm::u8vec3 c = image.at(x, y);
      colours.insert(uint32_t(c.r) << 16 | uint32_t(c.g) << 8 | c.b);
    }
  }
  return colours.size();
}

// Pixels of the map's background (25, 25, 30) in a rectangle.
size_t mapBackground(const Rgb8Image& image, int x0, int y0, int x1, int y1) {
  size_t count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) count += image.at(x, y) == glm::u8vec3(25, 25, 30);
  }
  return count;
}

}  // namespace

TEST_CASE("the viewer under Xvfb shows the scene and, with --sidebar shown, its tools beside it") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 256, 1);
  const std::filesystem::path screenshot = directory / "viewer.png";
  const ViewerRun run = runTriwalk(directory, "view --sidebar shown --dataset " + (directory / "data").string() +
                                                  " --frames 8 --screenshot " + screenshot.string());
  INFO("log: " << run.log);
  REQUIRE(run.status == 0);
  CHECK(run.log.find("live decimation: errors at 256x128, centroid destinations; warp mesh (grazing-angle 4.0 deg, "
                     "simplified 0.25 px mesh); blend epsilon 0.050, r_min 0.10 m, distance weights; holes raw;") !=
        std::string::npos);
  CHECK(run.log.find("; served-samples cost; runs to 1.36 x the dense mean error\n") != std::string::npos);
  REQUIRE(std::filesystem::exists(screenshot));
  const Rgb8Image image = readPng(screenshot);
  CHECK(image.width == 1280);
  CHECK(image.height == 720);

  // The walkthrough, left of the sidebar (a third of the 1280 pixels): the
  // room's smooth colours, not the single clear colour of an empty frame.
  CHECK(distinctColours(image, 20, 620, 820, 715) > 200);
  // The sidebar's map: its background fills most of its canvas, with the
  // triangulation drawn over it; none of it over the scene.
  CHECK(mapBackground(image, 860, 40, 1275, 140) > 2000);
  CHECK(mapBackground(image, 0, 0, 850, 720) == 0);
}

TEST_CASE("the viewer starts with the scene filling the window, and remembers the sidebar as it was left") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 256, 1);
  const std::filesystem::path screenshot = directory / "viewer.png";
  const std::string view = "view --dataset " + (directory / "data").string() + " --frames 4 --screenshot " + screenshot.string();
  // First start, nothing kept: the scene everywhere, no tools.
  const ViewerRun first = runTriwalk(directory, view);
  INFO("log: " << first.log);
  REQUIRE(first.status == 0);
  const Rgb8Image whole = readPng(screenshot);
  CHECK(distinctColours(whole, 900, 620, 1275, 715) > 200);
  CHECK(mapBackground(whole, 0, 0, 1280, 720) == 0);
  // The view covers the window: against the view alone (--hide-ui), only the hint's letters differ.
  REQUIRE(runTriwalk(directory, view + " --hide-ui").status == 0);
  const Rgb8Image alone = readPng(screenshot);
  size_t same = 0;
  for (size_t i = 0; i < whole.pixels.size(); ++i) same += whole.pixels[i] == alone.pixels[i];
  const double coverage = double(same) / double(whole.pixels.size());
  INFO("the view covers " << coverage << " of the window at start");
  CHECK(coverage >= 0.99);
  CHECK_FALSE(std::filesystem::exists(directory / "config" / "triwalk" / "viewer.json"));  // a scripted run keeps nothing

  // As Tab leaves it: shown.
  std::filesystem::create_directories(directory / "config" / "triwalk");
  writeTextFileAtomically(directory / "config" / "triwalk" / "viewer.json", "{\"sidebar\": true}\n");
  REQUIRE(runTriwalk(directory, view).status == 0);
  const Rgb8Image withTools = readPng(screenshot);
  CHECK(mapBackground(withTools, 860, 40, 1275, 140) > 2000);
  // With the tools, the view keeps the two thirds left of them: none of their pixels is over it.
  CHECK(mapBackground(withTools, 0, 0, 850, 720) == 0);
  // --sidebar hidden overrides what was kept.
  REQUIRE(runTriwalk(directory, view + " --sidebar hidden").status == 0);
  CHECK(mapBackground(readPng(screenshot), 0, 0, 1280, 720) == 0);
  // A damaged file: one line, and the defaults.
  writeTextFileAtomically(directory / "config" / "triwalk" / "viewer.json", "{\"sidebar\": ");
  const ViewerRun damaged = runTriwalk(directory, view);
  REQUIRE(damaged.status == 0);
  CHECK(damaged.log.find("viewer.json: not the viewer's preferences") != std::string::npos);
  CHECK(mapBackground(readPng(screenshot), 0, 0, 1280, 720) == 0);
}

TEST_CASE("two scripted screenshots with the same arguments are identical, and --hide-ui takes the view alone") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 256, 1);
  const std::string view = "view --dataset " + (directory / "data").string() + " --frames 6 --screenshot ";
  // The sidebar shown: the map's colours, the decimation's state and the
  // panels' text all wait for what they show.
  REQUIRE(runTriwalk(directory, view + (directory / "a.png").string() + " --sidebar shown").status == 0);
  REQUIRE(runTriwalk(directory, view + (directory / "b.png").string() + " --sidebar shown").status == 0);
  const Rgb8Image a = readPng(directory / "a.png"), b = readPng(directory / "b.png");
  CHECK(a.pixels == b.pixels);
  CHECK(mapBackground(a, 860, 40, 1275, 140) > 2000);  // the tools are in it

  // --hide-ui: the scene as without the sidebar, but for the hint at the top left.
  REQUIRE(runTriwalk(directory, view + (directory / "plain.png").string() + " --sidebar hidden").status == 0);
  REQUIRE(runTriwalk(directory, view + (directory / "alone.png").string() + " --hide-ui").status == 0);
  const Rgb8Image plain = readPng(directory / "plain.png"), alone = readPng(directory / "alone.png");
  REQUIRE(plain.width == alone.width);
  size_t differing = 0, outsideHint = 0;
  for (int y = 0; y < plain.height; ++y) {
    for (int x = 0; x < plain.width; ++x) {
      if (plain.at(x, y) == alone.at(x, y)) continue;
      ++differing;
      outsideHint += x > 260 || y > 30;
    }
  }
  CHECK(differing > 100);  // the hint's letters
  CHECK(outsideHint == 0);
  const ViewerRun both = runTriwalk(directory, view + (directory / "c.png").string() + " --hide-ui --sidebar shown");
  CHECK(both.status != 0);
  CHECK(both.log.find("--hide-ui: shows no tools: leave out --sidebar shown") != std::string::npos);
}

TEST_CASE("a walk recorded in the viewer, saved, loaded and played passes through the recorded positions within 1 cm") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 256, 1);
  // A walk with its times, a pause in it, turning through north.
  CameraPath walk;
  walk.poses = {{{0.2f, 0.2f, 1.6f}, 340.0f, 0.0f},
                {{0.7f, 0.5f, 1.6f}, 10.0f, 5.0f},
                {{1.2f, 0.4f, 1.6f}, 60.0f, 0.0f},
                {{1.2f, 0.4f, 1.6f}, 60.0f, 0.0f},
                {{1.5f, 0.1f, 1.6f}, 120.0f, -5.0f}};
  walk.seconds = {0.0, 0.5, 1.0, 1.2, 1.5};
  writeCameraPath(directory / "walk.txt", walk);
  const std::string view = "view --hide-ui --dataset " + (directory / "data").string() + " --frames 50 --screenshot " +
                           (directory / "shot.png").string();
  // Played from the file while recording: frame k shows, and records, the
  // walk at k/30 s.
  const ViewerRun first = runTriwalk(directory, view + " --path " + (directory / "walk.txt").string() + " --record " +
                                                    (directory / "recorded.txt").string());
  INFO("log: " << first.log);
  REQUIRE(first.status == 0);
  CHECK(first.log.find("saved the walk") != std::string::npos);
  const CameraPath recorded = readCameraPath(directory / "recorded.txt");
  REQUIRE(recorded.timed());
  CHECK(pathDuration(recorded, 30.0) == doctest::Approx(49.0 / 30.0).epsilon(1e-4));
  for (size_t i = 0; i < walk.poses.size(); ++i) {
    INFO("pose " << i);
    CHECK(glm::distance(poseAt(recorded, walk.seconds[i], 30.0).position, walk.poses[i].position) < 0.01f);
  }
  // The recording played back and recorded again passes through every recorded position.
  const ViewerRun second = runTriwalk(directory, view + " --path " + (directory / "recorded.txt").string() +
                                                     " --record " + (directory / "again.txt").string());
  REQUIRE(second.status == 0);
  const CameraPath again = readCameraPath(directory / "again.txt");
  for (size_t i = 0; i < recorded.poses.size(); ++i) {
    INFO("recorded pose " << i << " at " << recorded.seconds[i] << " s");
    CHECK(glm::distance(poseAt(again, recorded.seconds[i], 30.0).position, recorded.poses[i].position) < 0.01f);
  }
  // The same walk in a video, at its recorded speed: 1.63 s at 10 frames a second.
  const ViewerRun video = runTriwalk(directory, "render --dataset " + (directory / "data").string() + " --path " +
                                                    (directory / "recorded.txt").string() + " --size 160x96 --fps 10 "
                                                    "--video " + (directory / "walk.mp4").string(), false);
  INFO("log: " << video.log);
  REQUIRE(video.status == 0);
  const VideoInfo info = readVideoInfo(directory / "walk.mp4");
  CHECK(info.frames == 18);  // 0 .. 1.6 s every 0.1 s, then the end at 1.633 s
  CHECK(info.seconds == doctest::Approx(1.8).epsilon(0.01));
}

TEST_CASE("the view's overlays: trust everywhere, and the error against a sample only near one") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 256, 1);  // samples 4/3 m apart in x, 1 m in y
  // Near the sample at (4/3, 1), and in the middle of a cell, 0.83 m from every sample.
  for (const auto& [name, pose] : {std::pair{"near", "1.40 1.05 1.5 20 0"}, std::pair{"far", "2.0 0.5 1.5 20 0"}}) {
    writeTextFileAtomically(directory / (std::string(name) + ".txt"), std::string(pose) + "\n");
  }
  auto shot = [&](const std::string& at, const std::string& overlay) {
    const std::filesystem::path file = directory / (at + "_" + overlay + ".png");
    const ViewerRun run = runTriwalk(directory, "view --hide-ui --dataset " + (directory / "data").string() + " --frames 4 --path " +
                                                   (directory / (at + ".txt")).string() + " --overlay " + overlay +
                                                   " --screenshot " + file.string());
    INFO("log: " << run.log);
    REQUIRE(run.status == 0);
    return readPng(file);
  };
  // Pixels that differ, outside the colour bar's corner (bottom left).
  auto differing = [](const Rgb8Image& a, const Rgb8Image& b) {
    size_t count = 0;
    for (int y = 0; y < a.height - 90; ++y) {
      for (int x = 0; x < a.width; ++x) count += a.at(x, y) != b.at(x, y);
    }
    return double(count) / double(a.width * (a.height - 90));
  };
  const Rgb8Image nearPlain = shot("near", "none"), farPlain = shot("far", "none");
  CHECK(differing(nearPlain, shot("near", "trust")) > 0.8);
  CHECK(differing(nearPlain, shot("near", "error")) > 0.8);
  CHECK(differing(farPlain, shot("far", "error")) == 0.0);  // no sample within 0.5 m: the scene alone, and the note
  // The colour bar is there whenever an overlay is.
  const Rgb8Image farError = shot("far", "error");
  size_t barPixels = 0;
  for (int x = 0; x < 400; ++x) barPixels += farError.at(x, 720 - 40) != farPlain.at(x, 720 - 40);
  CHECK(barPixels > 200);
}

TEST_CASE("keys typed into the viewer (xdotool under Xvfb): F1 lists every control view --help lists, T colours by trust, W walks, N steps onto a reference, R saves the walk, V exports it as a video, Ctrl+Q quits") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 256, 1);
  // A person at the keyboard: each key waits for the screenshot that shows its effect.
  const std::string script = R"(set -u
cd ")" + directory.path().string() + R"("
XDG_CONFIG_HOME=config )" + std::string(TRIWALK_BINARY) + R"( view --dataset data --sidebar hidden --record walk.txt > viewer.log 2>&1 &
viewer=$!
window=$(xdotool search --sync --name '^triwalk$' | head -1)
xdotool windowfocus --sync "$window"
shot() { xdotool key F12; for i in $(seq 1 1200); do [ -e "$1" ] && return 0; sleep 0.1; done; echo "no $1"; exit 1; }
sleep 5
xdotool key F1; sleep 2; shot triwalk_screenshot_000.png
xdotool key F1; sleep 2; shot triwalk_screenshot_001.png
xdotool key t; sleep 2; shot triwalk_screenshot_002.png
xdotool key t
xdotool keydown w; sleep 2; xdotool keyup w
xdotool key n; sleep 1
xdotool key r
for i in $(seq 1 600); do [ -e walk.txt ] && break; sleep 0.1; done
xdotool key v
for i in $(seq 1 1800); do [ -e walk.mp4 ] && break; sleep 0.1; done
xdotool key ctrl+q
wait $viewer
)";
  writeTextFileAtomically(directory / "keys.sh", script);
  const std::string command = "xvfb-run -a -s '-screen 0 1280x800x24' bash " + (directory / "keys.sh").string() + " > " +
                              (directory / "keys.log").string() + " 2>&1";
  const int status = std::system(command.c_str());
  INFO("script: " << testing::readTextFileOrEmpty(directory / "keys.log") << "\nviewer: "
                  << testing::readTextFileOrEmpty(directory / "viewer.log"));
  REQUIRE(status == 0);

  // F1: a window over the view with a line of text for every control
  // `view --help` lists, and its title.
  const ViewerRun help = runTriwalk(directory, "view --help", false);
  // Its controls: the indented lines after "Controls:".
  size_t controls = 0;
  {
    std::istringstream lines(help.log.substr(help.log.find("Controls:\n") + 10));
    for (std::string line; std::getline(lines, line) && line.rfind("  ", 0) == 0;) ++controls;
  }
  // The list, then the same view without it: they differ by the list alone.
  const Rgb8Image listing = readPng(directory / "triwalk_screenshot_000.png");
  const Rgb8Image plain = readPng(directory / "triwalk_screenshot_001.png");
  // The list's window: its title bar (ImGui's dark style, active title
  // colour) gives its top and sides; it ends where its left edge stops
  // differing from the view without it.
  int top = listing.height, left = listing.width, right = -1;
  for (int y = 0; y < listing.height; ++y) {
    for (int x = 0; x < listing.width; ++x) {
      if (listing.at(x, y) != glm::u8vec3(41, 74, 122)) continue;
      top = std::min(top, y), left = std::min(left, x), right = std::max(right, x);
    }
  }
  REQUIRE(right > left);
  int bottom = top;
  while (bottom + 1 < listing.height && listing.at(left + 2, bottom + 1) != plain.at(left + 2, bottom + 1)) ++bottom;
  REQUIRE(bottom > top + 100);
  // Lines of text: bands of rows holding near-white letters inside the window.
  int lines = 0;
  bool inLine = false;
  for (int y = top; y <= bottom; ++y) {
    bool letters = false;
    for (int x = left; x <= right && !letters; ++x) {
      const glm::u8vec3 c = listing.at(x, y);
      letters = c.r > 200 && c.g > 200 && c.b > 200;
    }
    lines += letters && !inLine;
    inLine = letters;
  }
  CHECK(controls >= 10);  // the help was read
  CHECK(size_t(lines) == controls + 1);  // the title, then one line a control

  // T: the trust colours over the whole view.
  const Rgb8Image trust = readPng(directory / "triwalk_screenshot_002.png");
  size_t changed = 0;
  for (size_t i = 0; i < trust.pixels.size(); ++i) changed += trust.pixels[i] != plain.pixels[i];
  CHECK(changed > trust.pixels.size() / 2);

  // The walk, recorded from the start and saved by R: W moved the walker
  // along the view, and N put them on a reference, where its panorama was taken.
  const CameraPath walk = readCameraPath(directory / "walk.txt");
  REQUIRE(walk.timed());
  REQUIRE(walk.poses.size() >= 3);
  float furthestAhead = 0.0f;  // the walker starts looking along +x
  for (const CameraPose& pose : walk.poses) furthestAhead = std::max(furthestAhead, pose.position.x - walk.poses.front().position.x);
  CHECK(furthestAhead > 0.5f);
  const Dataset dataset = Dataset::open(directory / "data");
  float nearestSample = 1e9f;
  for (int i = 0; i < dataset.sampleCount(); ++i) {
    nearestSample = std::min(nearestSample, glm::distance(glm::vec2(walk.poses.back().position), glm::vec2(dataset.sample(i).position)));
  }
  CHECK(nearestSample < 1e-3f);

  // V: the walk as a video at the window's size, every 1/30 s of it, its end included.
  REQUIRE(std::filesystem::exists(directory / "walk.mp4"));
  const VideoInfo video = readVideoInfo(directory / "walk.mp4");
  CHECK(video.width == 1280);
  CHECK(video.height == 720);
  CHECK(size_t(video.frames) == frameCount(walk, 30.0));
  CHECK(video.seconds == doctest::Approx(double(frameCount(walk, 30.0)) / 30.0).epsilon(0.01));
  std::vector<std::string> videos;
  for (const auto& entry : std::filesystem::directory_iterator(directory.path())) {
    if (entry.path().filename().string().find(".mp4") != std::string::npos) videos.push_back(entry.path().filename().string());
  }
  CHECK(videos == std::vector<std::string>{"walk.mp4"});  // no temporary file left beside it
}

TEST_CASE("view --help lists every key and mouse control") {
  testing::TemporaryDirectory directory;
  const ViewerRun help = runTriwalk(directory, "view --help", false);
  REQUIRE(help.status == 0);
  for (const char* control : {"W A S D, arrow keys", "Shift", "drag", "Tab", "F1 or ?", "F12", "click on the map", "N, B",
                              "play the walk", "record the walk", "Esc", "T", "E"}) {
    CHECK(help.log.find(control) != std::string::npos);
  }
  CHECK(help.log.find("--sidebar") != std::string::npos);
}

TEST_CASE("the live decimation goes on with the errors and the cost a selection was made with, and bad ones fail early") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 4, 3, 256, 1);
  const std::string data = " --dataset " + (directory / "data").string();
  const std::filesystem::path selection = directory / "selection.json";
  const ViewerRun decimated =
      runTriwalk(directory, "decimate --quiet --target 6 --refine-radius 0 --error-stride 2 --cost centroid --source-mesh grid "
                            "--blend-weights reliability --grazing-angle 6" + data + " --out " + selection.string(), false);
  INFO("decimate: " << decimated.log);
  REQUIRE(decimated.status == 0);
  const std::string view = "view" + data + " --selection " + selection.string() + " --frames 2 --screenshot " +
                           (directory / "viewer.png").string();

  // The viewer's own --source-mesh and --grazing-angle are the walker's.
  const ViewerRun continued = runTriwalk(directory, view + " --source-mesh simplified --grazing-angle 10");
  INFO("view: " << continued.log);
  REQUIRE(continued.status == 0);
  CHECK(continued.log.find("live decimation: errors at 256x128 (every other row and column), centroid destinations; "
                           "warp mesh (grazing-angle 6.0 deg); blend epsilon 0.050, r_min 0.10 m, reliability weights; "
                           "holes raw;") != std::string::npos);
  CHECK(continued.log.find("; centroid cost; runs to 1.36 x the dense mean error\n") != std::string::npos);
  const ViewerRun asked = runTriwalk(directory, view + " --error-stride 1");
  INFO("view --error-stride 1: " << asked.log);
  REQUIRE(asked.status == 0);
  CHECK(asked.log.find("live decimation: errors at 256x128, centroid destinations; warp mesh (grazing-angle 6.0 deg); "
                       "blend epsilon 0.050, r_min 0.10 m, reliability weights;") != std::string::npos);

  // "run to error" starts at the threshold a selection was made with.
  nlohmann::json absolute = nlohmann::json::parse(readTextFile(selection));
  absolute["settings"]["max_error"] = 2.5;
  absolute["settings"]["relative_error"] = 0.0;
  writeTextFileAtomically(directory / "absolute.json", absolute.dump());
  const ViewerRun atAbsolute = runTriwalk(directory, "view" + data + " --selection " + (directory / "absolute.json").string() +
                                                         " --frames 2 --screenshot " + (directory / "viewer.png").string());
  INFO("view absolute.json: " << atAbsolute.log);
  CHECK(atAbsolute.log.find("; centroid cost; runs to error 2.500\n") != std::string::npos);

  // Without a display: the option and the selection are checked before a window opens.
  const ViewerRun badOption = runTriwalk(directory, view + " --error-stride 3", false);
  CHECK(badOption.status != 0);
  CHECK(badOption.log.find("--error-stride: 3 not in {1,2,4}") != std::string::npos);
  CHECK(std::count(badOption.log.begin(), badOption.log.end(), '\n') == 1);
  nlohmann::json document = nlohmann::json::parse(readTextFile(selection));
  document["settings"]["error_stride"] = 3;
  writeTextFileAtomically(directory / "bad.json", document.dump());
  const ViewerRun badSelection = runTriwalk(
      directory, "view" + data + " --selection " + (directory / "bad.json").string() + " --frames 2 --screenshot " +
                     (directory / "viewer.png").string(), false);
  CHECK(badSelection.status != 0);
  CHECK(badSelection.log.find("bad.json: settings: error_stride: must be a power of two dividing the error panorama's "
                               "height (128), not 3") != std::string::npos);
  CHECK(std::count(badSelection.log.begin(), badSelection.log.end(), '\n') == 1);
  // A lattice asked of a selection whose errors are hole-filled.
  document["settings"]["error_stride"] = 1;
  document["settings"]["holes"] = "fill";
  writeTextFileAtomically(directory / "filled.json", document.dump());
  const ViewerRun filled = runTriwalk(directory, "view" + data + " --selection " + (directory / "filled.json").string() +
                                                     " --error-stride 2 --frames 2 --screenshot " +
                                                     (directory / "viewer.png").string(), false);
  CHECK(filled.status != 0);
  CHECK(filled.log.find("--error-stride: a lattice of pixels cannot be hole-filled: use it with a selection made with "
                        "--holes black or mark") != std::string::npos);
  CHECK(std::count(filled.log.begin(), filled.log.end(), '\n') == 1);
}

}  // namespace triwalk
