#pragma once
// Capture of a data set: the dense samples on parallel paths across the
// walkable area (as the paper's 30 paths x 15 images), or on a square
// lattice clipped to a walkable region, and held-out probes at random
// positions inside it, rendered headless and written as
// manifest.json + one OpenEXR per view.

#include "core/io/dataset.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

namespace triwalk {

struct CaptureOptions {
  int paths = 30;            // parallel paths, spread along the area's longer side
  int perPath = 15;          // samples per path, along the shorter side
  std::optional<float> spacing;  // metres; if set, derives paths and perPath from the area
  std::optional<glm::vec4> area;  // x0, y0, x1, y1; default: the scene's walkable area
  // A walkable region of any shape instead of the rectangle: samples on a
  // square lattice of `spacing` clipped to it (default spacing: about
  // paths x perPath samples), probes uniform inside it; stored in the
  // manifest.
  std::optional<WalkableRegion> region;
  std::optional<float> eyeHeight;  // metres above the floor; default: the scene's
  int width = 1024;          // panorama width; height = width / 2
  int faceSize = 0;          // cube face resolution, 0 = defaultCubeFaceSize(width)
  int probes = 20;
  unsigned seed = 1;
  // Draw door leaves (passable meshes). Default: open doors, since the
  // walkable region passes through them; a walker standing in a doorway
  // would otherwise see nothing but the leaf.
  bool closedDoors = false;
  bool quiet = false;
  // How to load the scene again, kept in the manifest's capture settings
  // ("scene"): what `render --truth` renders the truth from. Null: not kept.
  nlohmann::json sceneSource;
};

struct CapturePlan {
  std::vector<ViewRecord> samples;
  std::vector<ViewRecord> probes;
  int paths = 0;    // lattice columns over a region
  int perPath = 0;  // lattice rows over a region
  glm::vec4 area{0.0f};  // the rectangle, or the region's bounds
  float eyeZ = 0.0f;
  float spacing = 0.0f;  // between neighbouring samples (along a path for the rectangle)
  std::optional<WalkableRegion> region;
};

// Positions and file names of every view; validates the options.
CapturePlan planCapture(const Scene& scene, const CaptureOptions& options);

struct CaptureSummary {
  int samples = 0;
  int probes = 0;
  double seconds = 0.0;
  std::string glDescription;
  size_t sceneTriangles = 0;
};

// Renders and writes the data set into outDirectory (staged beside it and
// renamed into place, so an interrupted capture leaves nothing behind).
// Needs a current GL context.
CaptureSummary captureDataset(const Scene& scene, const std::string& sceneName, const CaptureOptions& options,
                              const std::filesystem::path& outDirectory);

}  // namespace triwalk
