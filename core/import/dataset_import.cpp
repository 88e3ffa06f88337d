#include "core/import/dataset_import.h"

#include "core/image/color.h"
#include "core/import/panorama_orientation.h"
#include "core/io/dataset.h"
#include "core/io/exr_io.h"
#include "core/io/png_io.h"
#include "core/io/staged_directory.h"
#include "core/selection/baselines.h"
#include "core/selection/selection_inputs.h"
#include "core/support/errors.h"
#include "core/support/progress.h"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace triwalk {

namespace {

// Two views closer than this in x, y would be one vertex of the triangulation.
constexpr double kSamePositionMetres = 1e-3;

std::string sizeText(glm::ivec2 size) { return std::to_string(size.x) + "x" + std::to_string(size.y); }

glm::ivec2 depthFileSize(const DepthFile& depth) {
  return depth.path.extension() == ".exr" ? exrFileSize(depth.path) : imageFileSize(depth.path);
}

// Everything that can be checked from headers and poses, before any pixel
// is decoded: sizes agree everywhere, the panorama is 2:1, positions are
// finite and distinct. Returns the panorama size.
glm::ivec2 checkViews(const std::vector<SourceView>& views, const std::vector<ViewPose>& poses) {
  glm::ivec2 size(0);
  std::string sizeSource;
  for (const SourceView& view : views) {
    const glm::ivec2 color = imageFileSize(view.color);
    if (color.x != 2 * color.y) {
      throw InputError(view.color.string(), "size " + sizeText(color) + " is not an equirectangular panorama (width = 2 x height)");
    }
    const glm::ivec2 depth = depthFileSize(view.depth);
    if (depth != color) {
      throw InputError(view.depth.path.string(), "size " + sizeText(depth) + " differs from its colour image's " + sizeText(color));
    }
    const glm::ivec2 mask = view.mask.empty() ? color : imageFileSize(view.mask);
    if (mask != color) {
      throw InputError(view.mask.string(), "size " + sizeText(mask) + " differs from its colour image's " + sizeText(color));
    }
    if (size == glm::ivec2(0)) {
      size = color;
      sizeSource = view.color.string();
    } else if (color != size) {
      throw InputError(view.color.string(), "size " + sizeText(color) + " differs from " + sizeSource + "'s " + sizeText(size));
    }
  }
  for (size_t i = 0; i < views.size(); ++i) {
    const glm::dvec3 p = poses[i].position;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw InputError(views[i].poseFile.string(), "view '" + views[i].name + "' has a non-finite position");
    }
    for (size_t j = 0; j < i; ++j) {
      if (glm::length(glm::dvec2(poses[j].position) - glm::dvec2(p)) < kSamePositionMetres) {
        throw InputError(views[i].poseFile.string(), "views '" + views[j].name + "' and '" + views[i].name +
                                                         "' are at the same position (within 1 mm in x, y)");
      }
    }
  }
  return size;
}

ColorImage linearColor(const std::filesystem::path& path) {
  static const std::array<float, 256> kLinear = [] {
    std::array<float, 256> table{};
    for (int i = 0; i < 256; ++i) table[size_t(i)] = srgbToLinear(float(i) / 255.0f);
    return table;
  }();
  const Rgb8Image bytes = readPng(path);
  ColorImage color(bytes.width, bytes.height);
  for (size_t i = 0; i < bytes.pixelCount(); ++i) {
    const glm::u8vec3 pixel = bytes.pixels[i];
    color.pixels[i] = {kLinear[pixel.r], kLinear[pixel.g], kLinear[pixel.b]};
  }
  return color;
}

struct ConvertedView {
  Panorama panorama;
  float yawDegrees = 0.0f;
  size_t invalidPixels = 0;
  double tiltRadians = 0.0;
  bool resampled = false;
};

ConvertedView convertView(const SourceView& view, const ViewPose& pose, const CaptureImportOptions& options) {
  ConvertedView converted;
  DecodedDepth depth = decodeDepthFile(view.depth);
  ColorImage color = linearColor(view.color);
  if (!view.mask.empty()) {
    const Rgb8Image mask = readPng(view.mask);
    for (size_t i = 0; i < mask.pixelCount(); ++i) {
      if (mask.pixels[i] == glm::u8vec3(0) && std::isfinite(depth.metres.pixels[i])) {
        depth.metres.pixels[i] = std::numeric_limits<float>::infinity();
        ++depth.invalidPixels;
      }
    }
  }
  converted.invalidPixels = depth.invalidPixels;
  mirrorColumns(color);
  mirrorColumns(depth.metres);
  convertToDistance(depth.metres, options.depthKind);
  Panorama camera{std::move(color), std::move(depth.metres)};
  converted.yawDegrees = float(yawDegrees(pose));
  converted.tiltRadians = tiltRadians(pose);
  if (converted.tiltRadians <= negligibleTiltRadians(camera.width())) {
    converted.panorama = std::move(camera);
  } else {
    converted.panorama = uprightPanorama(camera, pose.rotation, degreesToRadians(converted.yawDegrees));
    converted.resampled = true;
  }
  return converted;
}

}  // namespace

CaptureImportReport importCapture(const std::vector<SourceView>& views, const CaptureImportOptions& options,
                                  const std::string& sceneName, const nlohmann::json& provenance,
                                  const std::filesystem::path& out) {
  std::vector<ViewPose> poses;
  for (const SourceView& view : views) poses.push_back(toTriwalkFrame(view.pose, options.up, options.metresPerUnit));
  const glm::ivec2 size = checkViews(views, poses);

  const int probeCount = int(std::lround(options.probesFraction * double(views.size())));
  if (int(views.size()) - probeCount < 3) {
    throw InputError("probes_fraction", std::to_string(views.size()) + " views leave " +
                                              std::to_string(int(views.size()) - probeCount) + " samples; at least 3 are needed");
  }
  std::vector<bool> isProbe(views.size(), false);
  for (int index : randomSelection(int(views.size()), probeCount, options.seed)) isProbe[size_t(index)] = true;

  Manifest manifest;
  manifest.scene = sceneName;
  manifest.width = size.x;
  manifest.height = size.y;
  nlohmann::json names = {{"samples", nlohmann::json::array()}, {"probes", nlohmann::json::array()}};
  for (size_t i = 0; i < views.size(); ++i) {
    std::vector<ViewRecord>& records = isProbe[i] ? manifest.probes : manifest.samples;
    ViewRecord record;
    record.id = int(records.size());
    record.file = isProbe[i] ? probeFileName(record.id) : sampleFileName(record.id);
    record.position = glm::vec3(poses[i].position);
    records.push_back(record);
    names[isProbe[i] ? "probes" : "samples"].push_back(views[i].name);
  }
  validateManifest(manifest, out.string());

  StagedDirectory staging(out, kManifestFileName, "a triwalk data set");
  createViewFolders(staging.path());
  CaptureImportReport report;
  report.width = size.x;
  report.height = size.y;
  InterruptScope interruptScope;
  ProgressReporter progress("import", views.size(), options.quiet);
  SelectionInputKeeper selectionInputs(staging.path(), size);
  size_t sampleIndex = 0, probeIndex = 0;
  for (size_t i = 0; i < views.size(); ++i) {
    throwIfInterrupted();
    ConvertedView converted = convertView(views[i], poses[i], options);
    ViewRecord& record = isProbe[i] ? manifest.probes[probeIndex++] : manifest.samples[sampleIndex++];
    record.yawDegrees = converted.yawDegrees;
    writePanoramaExr(staging.path() / record.file, converted.panorama);
    selectionInputs.keep(record, !isProbe[i], converted.panorama);
    const size_t pixels = converted.panorama.distance.pixelCount();
    report.invalidDepthPixels += converted.invalidPixels;
    report.pixels += pixels;
    const double invalidFraction = double(converted.invalidPixels) / double(pixels);
    if (invalidFraction > report.mostInvalidFraction) {
      report.mostInvalidFraction = invalidFraction;
      report.mostInvalidView = views[i].name;
    }
    report.resampledViews += converted.resampled;
    report.largestTiltDegrees = std::max(report.largestTiltDegrees, converted.tiltRadians * 180.0 / std::numbers::pi);
    progress.advance();
  }
  progress.finish();
  report.samples = int(manifest.samples.size());
  report.probes = int(manifest.probes.size());
  report.seconds = progress.elapsedSeconds();

  manifest.capture = {{"imported", provenance},
                      {"depth_kind", depthKindName(options.depthKind)},
                      {"up", upAxisName(options.up)},
                      {"metres_per_unit", options.metresPerUnit},
                      {"probes_fraction", options.probesFraction},
                      {"probe_seed", options.seed},
                      {"invalid_depth_pixels", report.invalidDepthPixels},
                      {"resampled_upright", report.resampledViews},
                      {"names", names}};
  writeManifest(staging.path(), manifest);
  staging.commit();
  return report;
}

}  // namespace triwalk
