#pragma once
// What a decimation reads of every view, kept as a data set is written.
// Decimation loads each view at the error width and, for a sample, the
// simplified mesh it warps with; on a fresh capture it first had to decode
// every 1024x512 EXR, downsample it and simplify it (19 s of the main job's
// decimation). Capture and import write each view once, with its panorama
// in memory, so they keep both in the data set's stores
// (core/io/downsampled_panorama_store.h, core/synthesis/simplified_mesh_store.h)
// at the selection's defaults, and the decimation reads them back.

#include "core/image/image.h"
#include "core/io/dataset.h"
#include "core/io/downsampled_panorama_store.h"
#include "core/selection/triangle_error.h"
#include "core/synthesis/simplified_mesh_store.h"

#include <filesystem>

namespace triwalk {

class SelectionInputKeeper {
public:
  // For the data set being written into datasetDirectory, with panoramas
  // of fullSize.
  SelectionInputKeeper(const std::filesystem::path& datasetDirectory, glm::ivec2 fullSize);

  // Keeps view's copy at the default error width and, for a sample, its
  // simplified mesh with the selection's default warp options
  // (selectionErrorDefaults); full is the panorama just written as view's
  // file. Thread-safe.
  void keep(const ViewRecord& view, bool isSample, const Panorama& full);

  int errorWidth() const { return defaults_.width; }

private:
  TriangleErrorSettings defaults_;  // the errors a selection reads unless asked
  DownsampledPanoramaStore panoramas_;
  SimplifiedMeshStore meshes_;
};

}  // namespace triwalk
