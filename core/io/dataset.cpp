#include "core/io/dataset.h"

#include "core/image/panorama_resample.h"
#include "core/io/contained_path.h"
#include "core/io/exr_io.h"
#include "core/io/json_fields.h"
#include "core/support/errors.h"
#include "core/support/input_limits.h"
#include "core/support/stable_hash.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace triwalk {

namespace {

ViewRecord parseView(const JsonObject& object, bool isSample) {
  ViewRecord view;
  view.id = object.integer("id");
  if (view.id < 0) object.fail("id must not be negative");
  view.file = object.string("file");
  if (view.file.empty()) object.fail("empty file name");
  view.position = object.vec3("position");
  view.yawDegrees = float(object.numberOr("yaw_degrees", 0.0));
  if (isSample) {
    view.path = object.integerOr("path", -1);
    view.step = object.integerOr("step", -1);
  }
  return view;
}

nlohmann::json viewToJson(const ViewRecord& view, bool isSample) {
  nlohmann::json object = {{"id", view.id},
                           {"file", view.file},
                           {"position", {view.position.x, view.position.y, view.position.z}},
                           {"yaw_degrees", view.yawDegrees}};
  if (isSample) {
    object["path"] = view.path;
    object["step"] = view.step;
  }
  return object;
}

std::string formatPosition(glm::vec3 p) {
  std::ostringstream text;
  text << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  return text.str();
}

void validateViews(const std::vector<ViewRecord>& views, const std::string& kind, const std::string& subject) {
  std::map<int, size_t> ids;
  for (size_t i = 0; i < views.size(); ++i) {
    const glm::vec3 p = views[i].position;
    if (!withinCoordinateBound(p.x) || !withinCoordinateBound(p.y) || !withinCoordinateBound(p.z)) {
      throw InputError(subject, kind + " " + std::to_string(views[i].id) + ": position " + formatPosition(p) +
                                    " is farther than " + kCoordinateBoundText + " from the origin");
    }
    if (!(std::abs(views[i].yawDegrees) <= kMaxYawDegrees)) {
      throw InputError(subject, kind + " " + std::to_string(views[i].id) + ": yaw_degrees is not within +-" +
                                    std::to_string(int(kMaxYawDegrees)));
    }
    if (!ids.emplace(views[i].id, i).second) {
      throw InputError(subject, kind + " id " + std::to_string(views[i].id) + " appears twice");
    }
  }
}

}  // namespace

void validateManifest(const Manifest& manifest, const std::string& subject) {
  if (manifest.width <= 0 || manifest.height <= 0) throw InputError(subject, "width and height must be positive");
  if (manifest.width != 2 * manifest.height) {
    throw InputError(subject, "equirectangular panoramas need width = 2 x height, got " +
                                  std::to_string(manifest.width) + "x" + std::to_string(manifest.height));
  }
  if (manifest.samples.size() < 3) {
    throw InputError(subject, std::to_string(manifest.samples.size()) +
                                  " samples; at least 3 are needed to form a triangle");
  }
  if (manifest.samples.size() + manifest.probes.size() > kMaxViews) {
    throw InputError(subject, std::to_string(manifest.samples.size() + manifest.probes.size()) +
                                  " views; triwalk reads at most " + std::to_string(kMaxViews));
  }
  validateViews(manifest.samples, "sample", subject);
  validateViews(manifest.probes, "probe", subject);
  // The triangulation works on x, y: two samples there would be one vertex.
  std::map<std::pair<float, float>, int> positions;
  for (const ViewRecord& sample : manifest.samples) {
    auto [it, inserted] = positions.emplace(std::pair(sample.position.x, sample.position.y), sample.id);
    if (!inserted) {
      throw InputError(subject, "samples " + std::to_string(it->second) + " and " + std::to_string(sample.id) +
                                    " share the position x, y of " + formatPosition(sample.position));
    }
  }
}

Dataset Dataset::open(const std::filesystem::path& directory) {
  const std::filesystem::path manifestPath = directory / kManifestFileName;
  if (!std::filesystem::is_directory(directory)) {
    throw InputError(directory.string(), "data set directory does not exist");
  }
  const nlohmann::json document = readJsonFile(manifestPath);
  const std::string subject = manifestPath.string();
  const JsonObject root(document, subject);

  if (root.stringOr("format", "triwalk-dataset") != "triwalk-dataset") root.fail("not a triwalk data set manifest");
  const int version = root.integer("version");
  if (version != kDatasetFormatVersion) {
    root.fail("unknown format version " + std::to_string(version) + " (this triwalk reads version " +
              std::to_string(kDatasetFormatVersion) + ")");
  }
  const std::string projection = root.string("projection");
  if (projection != "equirectangular") root.fail("unsupported projection '" + projection + "'");

  Dataset dataset;
  dataset.directory_ = directory;
  Manifest& manifest = dataset.manifest_;
  manifest.scene = root.stringOr("scene", "");
  manifest.width = root.integer("width");
  manifest.height = root.integer("height");
  if (root.has("capture")) manifest.capture = root.object("capture").json();
  if (root.has("walkable")) manifest.walkable = WalkableRegion::fromJson(root.json().at("walkable"), subject);
  for (size_t i = 0; i < root.array("samples").size(); ++i) {
    manifest.samples.push_back(parseView(root.element("samples", i), true));
  }
  if (root.has("probes")) {
    for (size_t i = 0; i < root.array("probes").size(); ++i) {
      manifest.probes.push_back(parseView(root.element("probes", i), false));
    }
  }
  validateManifest(manifest, subject);
  dataset.indexIds();

  for (const auto& [views, kind] : {std::pair(&manifest.samples, "sample"), std::pair(&manifest.probes, "probe")}) {
    for (const ViewRecord& view : *views) {
      containedFile(directory, view.file, subject + ": " + kind + " " + std::to_string(view.id));
    }
  }
  return dataset;
}

std::string Dataset::fingerprint() const {
  StableHash hash;
  for (const ViewRecord& view : manifest_.samples) {
    hash.addValue(view.id);
    hash.addValue(view.position);
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash.value()));
  return text;
}

void Dataset::indexIds() {
  sampleIndexById_.clear();
  probeIndexById_.clear();
  for (size_t i = 0; i < manifest_.samples.size(); ++i) sampleIndexById_.emplace(manifest_.samples[i].id, int(i));
  for (size_t i = 0; i < manifest_.probes.size(); ++i) probeIndexById_.emplace(manifest_.probes[i].id, int(i));
}

int Dataset::sampleIndexOfId(int id) const {
  const auto found = sampleIndexById_.find(id);
  return found == sampleIndexById_.end() ? -1 : found->second;
}

int Dataset::probeIndexOfId(int id) const {
  const auto found = probeIndexById_.find(id);
  return found == probeIndexById_.end() ? -1 : found->second;
}

int Dataset::downsamplingFactor(int width, const std::string& option) const {
  if (width == 0 || width == manifest_.width) return 1;
  if (width < 0 || width > manifest_.width || manifest_.width % width != 0 || manifest_.height % (manifest_.width / width) != 0) {
    throw InputError(option, "width " + std::to_string(width) + " must divide the data set's width " +
                                 std::to_string(manifest_.width) + " (and its height) by a whole number");
  }
  return manifest_.width / width;
}

int largestWidthAtMost(glm::ivec2 fullSize, int limit) {
  for (int factor = 1; factor <= fullSize.y; ++factor) {
    if (fullSize.x % factor == 0 && fullSize.y % factor == 0 && fullSize.x / factor <= limit) return fullSize.x / factor;
  }
  return fullSize.x / fullSize.y;
}

int Dataset::largestWidthAtMost(int limit) const {
  return triwalk::largestWidthAtMost(glm::ivec2(manifest_.width, manifest_.height), limit);
}

Panorama Dataset::loadView(const ViewRecord& view, int width) const {
  const int factor = downsamplingFactor(width, "width");
  const std::filesystem::path path = directory_ / view.file;
  return downsamplePanorama(readPanoramaExr(path, glm::ivec2(manifest_.width, manifest_.height)), factor);
}

Dataset Dataset::withSamples(std::span<const int> indices) const { return withViews(indices, {}); }

Dataset Dataset::withViews(std::span<const int> indices, std::span<const int> probeIndices) const {
  Dataset subset;
  subset.directory_ = directory_;
  subset.manifest_.scene = manifest_.scene;
  subset.manifest_.width = manifest_.width;
  subset.manifest_.height = manifest_.height;
  subset.manifest_.capture = manifest_.capture;
  subset.manifest_.walkable = walkableRegion();
  subset.manifest_.samples.reserve(indices.size());
  for (int i : indices) subset.manifest_.samples.push_back(sample(i));
  subset.manifest_.probes.reserve(probeIndices.size());
  for (int i : probeIndices) subset.manifest_.probes.push_back(probe(i));
  subset.indexIds();
  return subset;
}

WalkableRegion Dataset::walkableRegion() const {
  if (!manifest_.walkable.empty()) return manifest_.walkable;
  const nlohmann::json& area = manifest_.capture.contains("area") ? manifest_.capture["area"] : nlohmann::json();
  if (area.is_array() && area.size() == 4 && std::all_of(area.begin(), area.end(), [](const auto& v) { return v.is_number(); })) {
    const glm::dvec2 lower(area[0].get<double>(), area[1].get<double>()), upper(area[2].get<double>(), area[3].get<double>());
    if (upper.x > lower.x && upper.y > lower.y) return WalkableRegion::rectangle(lower, upper);
  }
  glm::dvec2 lower(std::numeric_limits<double>::max()), upper(std::numeric_limits<double>::lowest());
  for (const ViewRecord& sample : manifest_.samples) {
    lower = glm::min(lower, glm::dvec2(sample.position));
    upper = glm::max(upper, glm::dvec2(sample.position));
  }
  return WalkableRegion::rectangle(lower, upper);
}

EquirectProjection Dataset::projection(const ViewRecord& view) const {
  return {manifest_.width, manifest_.height, degreesToRadians(view.yawDegrees)};
}

namespace {

std::string numberedFile(const char* format, int id) {
  char name[64];
  std::snprintf(name, sizeof name, format, id);
  return name;
}

}  // namespace

std::string sampleFileName(int id) { return numberedFile("samples/s%04d.exr", id); }
std::string probeFileName(int id) { return numberedFile("probes/p%04d.exr", id); }

void createViewFolders(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory / "samples", error);
  std::filesystem::create_directories(directory / "probes", error);
  if (error) throw InputError(directory.string(), "cannot create directory: " + error.message());
}

void writeManifest(const std::filesystem::path& directory, const Manifest& manifest) {
  const std::filesystem::path path = directory / kManifestFileName;
  validateManifest(manifest, path.string());
  nlohmann::json samples = nlohmann::json::array();
  for (const ViewRecord& view : manifest.samples) samples.push_back(viewToJson(view, true));
  nlohmann::json probes = nlohmann::json::array();
  for (const ViewRecord& view : manifest.probes) probes.push_back(viewToJson(view, false));
  nlohmann::json document = {{"format", "triwalk-dataset"},
                                   {"version", kDatasetFormatVersion},
                                   {"scene", manifest.scene},
                                   {"projection", "equirectangular"},
                                   {"units", "metres"},
                                   {"width", manifest.width},
                                   {"height", manifest.height},
                                   {"capture", manifest.capture},
                                   {"samples", samples},
                                   {"probes", probes}};
  if (!manifest.walkable.empty()) document["walkable"] = manifest.walkable.toJson();
  writeJsonFile(path, document);
}

}  // namespace triwalk
