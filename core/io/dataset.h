#pragma once
// The captured data set: manifest.json plus one OpenEXR per view.
//
// manifest.json (format version 1):
// {
//   "format": "triwalk-dataset", "version": 1,
//   "scene": "builtin", "projection": "equirectangular", "units": "metres",
//   "width": 1024, "height": 512,
//   "capture": { "paths": 30, "per_path": 15, ... }            (optional, informative)
//   "samples": [ {"id": 0, "file": "samples/s0000.exr", "position": [x, y, z],
//                 "yaw_degrees": 0, "path": 0, "step": 0}, ... ],
//   "probes":  [ {"id": 0, "file": "probes/p0000.exr", "position": [x, y, z],
//                 "yaw_degrees": 0}, ... ],
//   "walkable": {"polygons": [...]}                               (optional, core/geometry/walkable_region.h)
// }
// Samples are the dense reference candidates; "path"/"step" place a sample
// on the capture's grid of parallel paths (-1 when unknown). Probes are
// held-out views, never references.

#include "core/geometry/projection.h"
#include "core/geometry/walkable_region.h"
#include "core/image/image.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace triwalk {

constexpr int kDatasetFormatVersion = 1;
constexpr const char* kManifestFileName = "manifest.json";

struct ViewRecord {
  int id = 0;
  std::string file;          // relative to the data set directory
  glm::vec3 position{0.0f};  // metres
  float yawDegrees = 0.0f;
  int path = -1;  // index of the capture path, -1 when unknown
  int step = -1;  // index along the path, -1 when unknown
};

struct Manifest {
  std::string scene;
  int width = 0;
  int height = 0;
  nlohmann::json capture = nlohmann::json::object();  // capture settings, informative
  std::vector<ViewRecord> samples;
  std::vector<ViewRecord> probes;
  WalkableRegion walkable;  // empty when the manifest does not give one
};

class Dataset {
public:
  // Reads manifest.json and validates it (version, sizes, ids, positions,
  // every referenced file exists). Throws InputError naming the file.
  static Dataset open(const std::filesystem::path& directory);

  const Manifest& manifest() const { return manifest_; }
  const std::filesystem::path& directory() const { return directory_; }
  std::filesystem::path manifestPath() const { return directory_ / kManifestFileName; }
  int sampleCount() const { return int(manifest_.samples.size()); }
  // 16 hex digits that name the samples (their ids and positions): a
  // selection records it, so that one made for another data set is
  // refused as such. Not the panorama size: a selection names samples by
  // id and position, and holds for a capture of the same positions at
  // another width (docs/RESULTS.md renders one selection from captures at
  // 512, 1024 and 2048).
  std::string fingerprint() const;
  int probeCount() const { return int(manifest_.probes.size()); }
  const ViewRecord& sample(int index) const { return manifest_.samples.at(size_t(index)); }
  const ViewRecord& probe(int index) const { return manifest_.probes.at(size_t(index)); }

  // The data set with only the given samples (indices, sorted) and no
  // probes, over the same walkable region and files: a tile of a tiled
  // decimation loads only its views. Sample i of it is sample indices[i].
  Dataset withSamples(std::span<const int> indices) const;
  // The same with the given probes too (indices, sorted): probe i of it is
  // probe probeIndices[i].
  Dataset withViews(std::span<const int> indices, std::span<const int> probeIndices) const;

  // Index of the sample with this id, or -1.
  int sampleIndexOfId(int id) const;
  int probeIndexOfId(int id) const;

  // Loads one view's panorama, validating its size against the manifest
  // and its values (see readPanoramaExr). A width below the data set's
  // downsamples by an integer factor (see downsamplePanorama); 0 = full.
  Panorama loadView(const ViewRecord& view, int width = 0) const;

  // Throws InputError (naming option) unless width is 0 or divides the
  // data set's width by an integer factor.
  int downsamplingFactor(int width, const std::string& option) const;
  // The largest width not above `limit` that downsamplingFactor accepts
  // (the full width if it is not above the limit).
  int largestWidthAtMost(int limit) const;

  EquirectProjection projection(const ViewRecord& view) const;

  // The walkthrough space: the manifest's walkable region, else the
  // capture's rectangle, else the bounding box of the samples.
  WalkableRegion walkableRegion() const;

private:
  // Ids to indices, so that reading a selection of n samples is O(n), not O(n^2).
  void indexIds();

  std::filesystem::path directory_;
  Manifest manifest_;
  std::unordered_map<int, int> sampleIndexById_, probeIndexById_;
};

// The largest width not above `limit` that divides panoramas of fullSize
// (and their height) by a whole number: Dataset::largestWidthAtMost for a
// data set still being written.
int largestWidthAtMost(glm::ivec2 fullSize, int limit);

// The file of sample or probe id in a data set triwalk writes
// ("samples/s0007.exr", "probes/p0003.exr").
std::string sampleFileName(int id);
std::string probeFileName(int id);
// Creates the samples/ and probes/ folders those files go in.
void createViewFolders(const std::filesystem::path& directory);

// Validates a manifest (also used before writing one).
void validateManifest(const Manifest& manifest, const std::string& subject);

// Writes manifest.json atomically into directory.
void writeManifest(const std::filesystem::path& directory, const Manifest& manifest);

}  // namespace triwalk
