// Captures in other tools' layouts (core/import): export and import back
// in each layout, tilted cameras resampled upright, depth kinds and
// encodings, probes held out, and every bad input named in one line.

#include "core/image/color.h"
#include "core/import/dataset_export.h"
#include "core/import/dataset_import.h"
#include "core/import/panorama_orientation.h"
#include "core/io/dataset.h"
#include "core/io/downsampled_panorama_store.h"
#include "core/io/exr_io.h"
#include "core/io/png_io.h"
#include "core/synthesis/simplified_mesh_store.h"
#include "tests/analytic_scene.h"
#include "tests/test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace triwalk {

namespace {

std::vector<SourceView> scan(CaptureLayout layout, const std::filesystem::path& in, LayoutOptions options = {}) {
  return scanCaptureLayout(layout, in, options);
}

CaptureImportReport importQuietly(const std::vector<SourceView>& views, const std::filesystem::path& out,
                                  CaptureImportOptions options = {}) {
  options.quiet = true;
  return importCapture(views, options, "test", nlohmann::json::object(), out);
}

// The original view a round-tripped one came from: export names views
// after their files (s3, p0).
const ViewRecord& originalView(const Dataset& original, const std::string& name) {
  for (const auto* views : {&original.manifest().samples, &original.manifest().probes}) {
    for (const ViewRecord& view : *views) {
      if (std::filesystem::path(view.file).stem().string() == name) return view;
    }
  }
  FAIL("no view named " << name);
  throw std::logic_error("unreachable");
}

// A room with a box, and a panorama of it seen by a camera turned by
// rotation (camera to world), in the photo convention, as a tool that
// knows nothing of triwalk would store it.
testing::AnalyticScene roomWithBox() {
  testing::AnalyticScene scene;
  scene.room = testing::AnalyticScene::Room{{-3.0f, -3.0f, 0.0f}, {4.0f, 3.0f, 3.0f}, false};
  scene.boxes.push_back({{1.5f, -0.5f, 0.0f}, {2.0f, 0.5f, 1.2f}});
  return scene;
}

Panorama photoOfTurnedCamera(const testing::AnalyticScene& scene, glm::vec3 position, const glm::mat3& rotation,
                             int width, DepthKind kind) {
  const EquirectProjection camera{width, width / 2, 0.0f};
  Panorama photo{ColorImage(width, width / 2), ScalarImage(width, width / 2)};
  for (int v = 0; v < width / 2; ++v) {
    for (int u = 0; u < width; ++u) {
      const glm::vec3 ray = camera.pixelDirection(width - 1 - u, v);  // photo column u is triwalk's W - 1 - u
      const testing::AnalyticHit hit = scene.trace(position, rotation * ray);
      photo.color.at(u, v) = hit.color;
      photo.distance.at(u, v) = depthOfKind(hit.distance, ray, kind);
    }
  }
  return photo;
}

void writeFolderView(const std::filesystem::path& in, const std::string& name, const Panorama& photo) {
  std::filesystem::create_directories(in / "color");
  std::filesystem::create_directories(in / "depth");
  writePng(in / "color" / (name + ".png"), toDisplayImage(photo.color));
  writeDepthExr(in / "depth" / (name + ".exr"), photo.distance);
}

double meanDisplayDifference(const ColorImage& a, const ColorImage& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.pixelCount(); ++i) {
    const glm::vec3 d = glm::abs(displayColor(a.pixels[i]) - displayColor(b.pixels[i]));
    sum += double(d.r + d.g + d.b) / 3.0;
  }
  return sum / double(a.pixelCount());
}

// The median of |a - b| / b over pixels with a surface in both.
double medianRelativeDistanceError(const ScalarImage& a, const ScalarImage& b) {
  std::vector<double> errors;
  for (size_t i = 0; i < a.pixelCount(); ++i) {
    if (std::isfinite(a.pixels[i]) && std::isfinite(b.pixels[i])) {
      errors.push_back(std::abs(double(a.pixels[i]) - double(b.pixels[i])) / double(b.pixels[i]));
    }
  }
  REQUIRE(errors.size() > a.pixelCount() / 2);
  std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(errors.size() / 2), errors.end());
  return errors[errors.size() / 2];
}

glm::mat3 rotationAbout(glm::vec3 axis, float degrees) {
  const float a = degreesToRadians(degrees);
  const glm::vec3 k = glm::normalize(axis);
  const glm::mat3 cross(glm::vec3(0, k.z, -k.y), glm::vec3(-k.z, 0, k.x), glm::vec3(k.y, -k.x, 0));
  return glm::mat3(1.0f) + std::sin(a) * cross + (1.0f - std::cos(a)) * cross * cross;
}

std::string matrixRow(const std::string& name, const glm::mat3& rotation, glm::vec3 position) {
  std::string row = name;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) row += "," + std::to_string(rotation[c][r]);
    row += "," + std::to_string(position[r]);
  }
  return row + ",0,0,0,1\n";
}

}  // namespace

TEST_CASE("export to each layout and import back: the same positions, yaws and images within the layout's precision") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 3, 3, 64, 2);
  {
    // Turned views: the yaw must survive the pose files and the mirrored columns.
    Dataset dataset = Dataset::open(directory / "data");
    Manifest manifest = dataset.manifest();
    for (size_t i = 0; i < manifest.samples.size(); ++i) manifest.samples[i].yawDegrees = -150.0f + 37.0f * float(i);
    writeManifest(directory / "data", manifest);
  }
  const Dataset original = Dataset::open(directory / "data");
  struct Case {
    CaptureLayout layout;
    float depthTolerance;  // 16-bit millimetres: half a unit; float EXR: exact
  };
  for (const Case& test : {Case{CaptureLayout::RealSee, 0.0005f + 1e-6f}, Case{CaptureLayout::Pano3D, 0.0f},
                           Case{CaptureLayout::Folder, 0.0f}}) {
    CAPTURE(captureLayoutName(test.layout));
    const std::filesystem::path exported = directory / (std::string("export_") + captureLayoutName(test.layout));
    const std::filesystem::path imported = directory / (std::string("import_") + captureLayoutName(test.layout));
    CHECK(exportDataset(original, test.layout, exported, true) == 11);
    CaptureImportOptions options;
    options.probesFraction = 0.0;
    const CaptureImportReport report = importQuietly(scan(test.layout, exported), imported, options);
    CHECK(report.samples == 11);
    CHECK(report.resampledViews == 0);
    const Dataset back = Dataset::open(imported);
    REQUIRE(back.sampleCount() == 11);
    for (int i = 0; i < back.sampleCount(); ++i) {
      const std::string name = back.manifest().capture["names"]["samples"][size_t(i)];
      CAPTURE(name);
      const ViewRecord& source = originalView(original, name);
      const ViewRecord& view = back.sample(i);
      CHECK(glm::length(view.position - source.position) < 1e-6f);
      const float yawError = std::remainder(view.yawDegrees - source.yawDegrees, 360.0f);
      CHECK(std::abs(yawError) < 1e-3f);
      const Panorama a = original.loadView(source), b = back.loadView(view);
      float colorError = 0.0f, depthError = 0.0f;
      bool infinityKept = true;
      for (size_t p = 0; p < a.color.pixelCount(); ++p) {
        const glm::vec3 d = glm::abs(displayColor(a.color.pixels[p]) - displayColor(b.color.pixels[p]));
        colorError = std::max({colorError, d.r, d.g, d.b});
        if (std::isinf(a.distance.pixels[p]) != std::isinf(b.distance.pixels[p])) infinityKept = false;
        if (std::isfinite(a.distance.pixels[p])) depthError = std::max(depthError, std::abs(a.distance.pixels[p] - b.distance.pixels[p]));
      }
      // Half a byte of sRGB, plus what half floats add.
      CHECK(colorError <= 0.5f / 255.0f + 2e-3f);
      CHECK(depthError <= test.depthTolerance);
      CHECK(infinityKept);
    }
  }
}

TEST_CASE("an import keeps what a decimation reads of each view, bit for bit what the written files give") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 2, 3, 512, 0);
  const Dataset original = Dataset::open(directory / "data");
  REQUIRE(exportDataset(original, CaptureLayout::Folder, directory / "exported", true) == 6);
  CaptureImportOptions options;
  options.probesFraction = 0.0;
  importQuietly(scan(CaptureLayout::Folder, directory / "exported"), directory / "imported", options);
  const Dataset back = Dataset::open(directory / "imported");
  REQUIRE(back.sampleCount() == 6);
  DownsampledPanoramaStore kept(back);
  const SimplifiedMeshStore meshes(back);
  for (int i = 0; i < back.sampleCount(); ++i) {
    const Panorama copy = kept.load(back.sample(i), 256);
    const Panorama fromFile = back.loadView(back.sample(i), 256);
    CHECK(copy.color.pixels == fromFile.color.pixels);
    CHECK(copy.distance.pixels == fromFile.distance.pixels);
    CHECK(std::filesystem::is_regular_file(meshes.file(back.sample(i), 256, WarpOptions{}.meshTolerancePixels)));
  }
  CHECK(kept.loaded() == 6);
  CHECK(kept.downsampled() == 0);
}

TEST_CASE("a tilted camera's panorama is resampled upright: it matches the upright view of the same place") {
  testing::TemporaryDirectory directory;
  const testing::AnalyticScene scene = roomWithBox();
  const int width = 256;
  const glm::vec3 position(0.0f, 0.3f, 1.5f);
  // A roll of 10 degrees and a pitch of 8: the forward axis stays in the x, z plane (yaw 0).
  const glm::mat3 rotation = rotationAbout({0, 1, 0}, 8.0f) * rotationAbout({1, 0, 0}, 10.0f);
  const std::filesystem::path in = directory / "capture";
  writeFolderView(in, "tilted", photoOfTurnedCamera(scene, position, rotation, width, DepthKind::CubeZ));
  // Two more upright views, so there is a triangle.
  writeFolderView(in, "a", photoOfTurnedCamera(scene, {1.0f, 0.0f, 1.5f}, glm::mat3(1.0f), width, DepthKind::CubeZ));
  writeFolderView(in, "b", photoOfTurnedCamera(scene, {0.0f, 1.0f, 1.5f}, glm::mat3(1.0f), width, DepthKind::CubeZ));
  std::ofstream(in / "poses.csv") << "name,m00,m01,m02,m03,m10,m11,m12,m13,m20,m21,m22,m23,m30,m31,m32,m33\n"
                                  << matrixRow("tilted", rotation, position) << matrixRow("a", glm::mat3(1.0f), {1.0f, 0.0f, 1.5f})
                                  << matrixRow("b", glm::mat3(1.0f), {0.0f, 1.0f, 1.5f});
  CaptureImportOptions options;
  options.probesFraction = 0.0;
  options.depthKind = DepthKind::CubeZ;
  const CaptureImportReport report = importQuietly(scan(CaptureLayout::Folder, in), directory / "data", options);
  CHECK(report.resampledViews == 1);
  CHECK(report.largestTiltDegrees == doctest::Approx(12.8).epsilon(0.02));

  const Dataset dataset = Dataset::open(directory / "data");
  const int tilted = 2;  // sorted by name: a, b, tilted
  REQUIRE(dataset.manifest().capture["names"]["samples"][size_t(tilted)] == "tilted");
  CHECK(std::abs(dataset.sample(tilted).yawDegrees) < 0.01f);
  const Panorama imported = dataset.loadView(dataset.sample(tilted));
  const Panorama upright = testing::renderPanorama(scene, position, width);
  // Nearest-pixel distances: off by at most about half a pixel along the surface.
  CHECK(medianRelativeDistanceError(imported.distance, upright.distance) < 0.005);
  CHECK(meanDisplayDifference(imported.color, upright.color) < 0.01);
  // Without the resampling (the tilted panorama taken as upright) both are far off.
  Panorama asStored = photoOfTurnedCamera(scene, position, rotation, width, DepthKind::Euclidean);
  mirrorColumns(asStored.color);
  mirrorColumns(asStored.distance);
  CHECK(medianRelativeDistanceError(asStored.distance, upright.distance) > 0.03);
  CHECK(meanDisplayDifference(asStored.color, upright.color) > 0.03);
  // The upright views' cube-z depth became distance along the ray.
  const Panorama a = dataset.loadView(dataset.sample(0));
  CHECK(medianRelativeDistanceError(a.distance, testing::renderPanorama(scene, {1.0f, 0.0f, 1.5f}, width).distance) < 1e-5);
}

TEST_CASE("folder layout: 16-bit millimetre depth of the horizontal kind, y-up poses in centimetres, probes held out by seed") {
  testing::TemporaryDirectory directory;
  const testing::AnalyticScene scene = roomWithBox();
  const int width = 64;
  const std::filesystem::path in = directory / "capture";
  std::filesystem::create_directories(in / "color");
  std::filesystem::create_directories(in / "depth");
  std::string poses = "name,x,y,z,yaw_deg\n";
  std::vector<glm::vec3> positions;
  for (int i = 0; i < 10; ++i) {
    const glm::vec3 position(-1.0f + 0.5f * float(i % 5), -1.0f + 1.2f * float(i / 5), 1.5f);
    positions.push_back(position);
    const std::string name = "view" + std::to_string(i);
    const Panorama photo = photoOfTurnedCamera(scene, position, glm::mat3(1.0f), width, DepthKind::Horizontal);
    writePng(in / "color" / (name + ".png"), toDisplayImage(photo.color));
    Gray16Image millimetres(width, width / 2);
    for (size_t p = 0; p < millimetres.pixelCount(); ++p) millimetres.pixels[p] = uint16_t(std::lround(photo.distance.pixels[p] * 1000.0f));
    writePng16(in / "depth" / (name + ".png"), millimetres);
    // y up, centimetres: (x, y, z) in triwalk is (x, -z, y) in the file... so the file holds (x, z, -y) * 100.
    char row[128];
    std::snprintf(row, sizeof row, "%s,%g,%g,%g,0\n", name.c_str(), 100.0 * position.x, 100.0 * position.z, -100.0 * position.y);
    poses += row;
  }
  std::ofstream(in / "poses.csv") << poses;
  LayoutOptions layoutOptions;
  layoutOptions.up = UpAxis::PlusY;
  CaptureImportOptions options;
  options.up = UpAxis::PlusY;
  options.metresPerUnit = 0.01;
  options.depthKind = DepthKind::Horizontal;
  options.probesFraction = 0.3;
  options.seed = 5;
  const CaptureImportReport report =
      importQuietly(scan(CaptureLayout::Folder, in, layoutOptions), directory / "data", options);
  CHECK(report.samples == 7);
  CHECK(report.probes == 3);
  const Dataset dataset = Dataset::open(directory / "data");
  const nlohmann::json& names = dataset.manifest().capture["names"];
  for (int i = 0; i < dataset.sampleCount(); ++i) {
    const std::string name = names["samples"][size_t(i)];
    const glm::vec3 expected = positions[size_t(std::stoi(name.substr(4)))];
    CHECK(glm::length(dataset.sample(i).position - expected) < 1e-5f);
    CHECK(std::abs(dataset.sample(i).yawDegrees) < 1e-4f);
    // Millimetres along the horizontal: within a millimetre along the ray
    // wherever the ray is not steep.
    const Panorama panorama = dataset.loadView(dataset.sample(i));
    const Panorama truth = testing::renderPanorama(scene, expected, width);
    for (int v = width / 8; v < 3 * width / 8; ++v) {
      for (int u = 0; u < width; ++u) CHECK(std::abs(panorama.distance.at(u, v) - truth.distance.at(u, v)) < 0.0015f);
    }
  }
  // The same seed holds out the same views; probes are never samples.
  const CaptureImportReport again =
      importQuietly(scan(CaptureLayout::Folder, in, layoutOptions), directory / "again", options);
  CHECK(again.probes == 3);
  CHECK(Dataset::open(directory / "again").manifest().capture["names"] == names);
  for (const auto& probe : names["probes"]) {
    CHECK(std::find(names["samples"].begin(), names["samples"].end(), probe) == names["samples"].end());
  }
}

TEST_CASE("bad captures give one line naming the file, before any image is converted, and write nothing") {
  testing::TemporaryDirectory directory;
  testing::writeAnalyticDataset(directory / "data", 2, 2, 32, 0);
  const Dataset original = Dataset::open(directory / "data");
  const std::filesystem::path out = directory / "out";
  // A fresh copy of the capture in the folder layout for each case.
  int copies = 0;
  const auto freshCapture = [&] {
    const std::filesystem::path in = directory / ("capture" + std::to_string(copies++));
    exportDataset(original, CaptureLayout::Folder, in, true);
    return in;
  };
  const auto importFolder = [&](const std::filesystem::path& in) {
    CaptureImportOptions options;
    options.probesFraction = 0.0;
    importQuietly(scan(CaptureLayout::Folder, in), out, options);
  };
  const auto expectNothingWritten = [&] {
    CHECK_FALSE(std::filesystem::exists(out));
    CHECK(testing::countEntries(out.parent_path(), out.filename().string() + ".partial-triwalk") == 0);
  };

  SUBCASE("an unreadable colour image") {
    const std::filesystem::path in = freshCapture();
    std::ofstream(in / "color" / "s1.png") << "not a png";
    testing::requireInputError([&] { importFolder(in); }, "s1.png", "cannot read image");
  }
  SUBCASE("a depth image of another size") {
    const std::filesystem::path in = freshCapture();
    writeDepthExr(in / "depth" / "s2.exr", ScalarImage(16, 8, 1.0f));
    testing::requireInputError([&] { importFolder(in); }, "s2.exr", "differs from its colour image's 32x16");
  }
  SUBCASE("a panorama that is not 2:1") {
    const std::filesystem::path in = freshCapture();
    writePng(in / "color" / "s0.png", Rgb8Image(32, 32));
    testing::requireInputError([&] { importFolder(in); }, "s0.png", "not an equirectangular panorama");
  }
  SUBCASE("views of different sizes") {
    const std::filesystem::path in = freshCapture();
    writePng(in / "color" / "s3.png", Rgb8Image(64, 32));
    writeDepthExr(in / "depth" / "s3.exr", ScalarImage(64, 32, 1.0f));
    testing::requireInputError([&] { importFolder(in); }, "s3.png", "differs from");
  }
  SUBCASE("a colour image without depth") {
    const std::filesystem::path in = freshCapture();
    std::filesystem::remove(in / "depth" / "s1.exr");
    testing::requireInputError([&] { importFolder(in); }, "s1.png", "no depth image");
  }
  SUBCASE("an 8-bit depth PNG") {
    const std::filesystem::path in = freshCapture();
    std::filesystem::remove(in / "depth" / "s1.exr");
    writePng(in / "depth" / "s1.png", Rgb8Image(32, 16));
    testing::requireInputError([&] { importFolder(in); }, "s1.png", "not a 16-bit PNG");
  }
  SUBCASE("a NaN depth") {
    const std::filesystem::path in = freshCapture();
    writeDepthExr(in / "depth" / "s1.exr", ScalarImage(32, 16, std::nanf("")));
    testing::requireInputError([&] { importFolder(in); }, "s1.exr", "NaN depth");
  }
  SUBCASE("a missing pose") {
    const std::filesystem::path in = freshCapture();
    std::ofstream(in / "poses.csv") << "s0,0,0,1.5,0\ns1,4,0,1.5,0\ns2,0,2,1.5,0\n";
    testing::requireInputError([&] { importFolder(in); }, "poses.csv", "no pose for view 's3'");
  }
  SUBCASE("a non-finite pose") {
    const std::filesystem::path in = freshCapture();
    std::ofstream(in / "poses.csv") << "s0,0,0,1.5,0\ns1,4,nan,1.5,0\ns2,0,2,1.5,0\ns3,4,2,1.5,0\n";
    testing::requireInputError([&] { importFolder(in); }, "poses.csv:2", "non-finite");
  }
  SUBCASE("a malformed pose row") {
    const std::filesystem::path in = freshCapture();
    std::ofstream(in / "poses.csv") << "s0,0,0,1.5,0\ns1,4,zero,1.5,0\n";
    testing::requireInputError([&] { importFolder(in); }, "poses.csv:2", "'zero' is not a number");
  }
  SUBCASE("a header where a pose should be") {
    const std::filesystem::path in = freshCapture();
    std::ofstream(in / "poses.csv") << "name,x,y,z,yaw_deg\nname,x,y,z,yaw_deg\n";
    testing::requireInputError([&] { importFolder(in); }, "poses.csv:2", "'x' is not a number");
  }
  SUBCASE("a pose matrix that is not a rotation") {
    const std::filesystem::path in = freshCapture();
    std::ofstream(in / "poses.csv") << "s0,2,0,0,0,0,1,0,0,0,0,1,1.5,0,0,0,1\n";
    testing::requireInputError([&] { importFolder(in); }, "poses.csv:1", "not a rotation");
  }
  SUBCASE("two views at one position") {
    const std::filesystem::path in = freshCapture();
    std::ofstream(in / "poses.csv") << "s0,0,0,1.5,0\ns1,4,0,1.5,0\ns2,0,2,1.5,0\ns3,0.0004,2,1.7,0\n";
    testing::requireInputError([&] { importFolder(in); }, "poses.csv", "'s2' and 's3' are at the same position");
  }
  SUBCASE("a realsee viewpoint without its depth scale") {
    const std::filesystem::path in = directory / "realsee";
    exportDataset(original, CaptureLayout::RealSee, in, true);
    std::filesystem::remove(in / "viewpoints" / "s2" / "depth_scale.txt");
    testing::requireInputError([&] { scan(CaptureLayout::RealSee, in); }, "depth_scale.txt", "does not exist");
  }
  SUBCASE("too few views left as samples") {
    const std::filesystem::path in = freshCapture();
    CaptureImportOptions options;
    options.probesFraction = 0.5;
    testing::requireInputError([&] { importQuietly(scan(CaptureLayout::Folder, in), out, options); }, "probes_fraction",
                               "at least 3");
  }
  SUBCASE("an output folder that is not a data set") {
    const std::filesystem::path in = freshCapture();
    std::filesystem::create_directories(out);
    std::ofstream(out / "notes.txt") << "mine";
    testing::requireInputError([&] { importFolder(in); }, out.string(), "not a triwalk data set");
    CHECK(std::filesystem::exists(out / "notes.txt"));
    std::filesystem::remove_all(out);
  }
  expectNothingWritten();
}

}  // namespace triwalk
