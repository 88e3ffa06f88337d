#pragma once
// Simplified source meshes kept beside a data set's panoramas
// (docs/DESIGN.md, "Simplified source meshes"). Simplifying a 1024x512
// reference costs meshoptimizer most of a second, five times the rest of
// preparing it for the GPU, so a walk into new triangles outran the
// viewer's loader. The triangles depend only on the view (its distances,
// position, yaw, width) and the warp options, so they are computed once
// and kept in DATASET/meshes/, one file per view, width and tolerance, under a key
// of all of these. A file whose key or checksum does not match, or that is
// malformed, is simplified again and replaced: it is a cache, never input
// the user must mend (core/io/derived_files.h).

#include "core/io/dataset.h"
#include "core/io/derived_files.h"
#include "core/synthesis/warp.h"

#include <atomic>
#include <filesystem>
#include <optional>
#include <vector>

namespace triwalk {

class SimplifiedMeshStore {
public:
  explicit SimplifiedMeshStore(const Dataset& dataset);
  // The store of the data set being written into datasetDirectory (capture,
  // import), before its manifest exists.
  explicit SimplifiedMeshStore(const std::filesystem::path& datasetDirectory);

  // The warp source of view (its panorama loaded at any width). With a
  // simplified mesh, its triangles come from the store when it holds them
  // for this very source, else they are simplified now and stored.
  WarpSource source(const ViewRecord& view, const Panorama& panorama, const WarpOptions& options);

  // The walking mesh of a simplified source (render/walkthrough/gpu_panorama.h)
  // for frames at `scale` of the window's side: its triangles simplified
  // further, to the tolerance t / scale in all for its own t, as indices
  // into source's vertices. From the store when it holds them for this
  // very source, else made now and stored.
  std::vector<uint32_t> walkingTriangles(const ViewRecord& view, const Panorama& panorama, const WarpSource& source,
                                         const WarpOptions& options, float scale);

  // Where view's triangles at this width and tolerance are kept: one file
  // per tolerance, so that commands run with different --mesh-tolerance
  // never replace (and simplify again) each other's. walkingScale > 0: the
  // file of the walking mesh for that scale.
  std::filesystem::path file(const ViewRecord& view, int width, float tolerancePixels, float walkingScale = 0.0f) const;

  // Sources whose triangles were read from the store, and simplified here
  // (walking meshes not counted).
  int loaded() const { return loaded_; }
  int simplified() const { return simplified_; }

private:
  std::optional<SimplifiedTriangles> load(const std::filesystem::path& path, uint64_t key, uint32_t vertexCount) const;
  void store(const std::filesystem::path& path, uint64_t key, const SimplifiedTriangles& triangles);

  DerivedFiles files_;
  std::atomic<int> loaded_ = 0, simplified_ = 0;
};

}  // namespace triwalk
