#pragma once
// The working set of reference panoramas for rendering (the paper's
// "working set management"): a least-recently-used cache of panoramas on
// the GPU, filled by a loader thread that reads and prepares them
// (OpenEXR decode, stretch test, tiling) so that a frame never waits on
// disk. The viewer asks for the current triangle's references and, at
// lower priority, its neighbours'; a panorama still loading is reported
// missing and the frame draws without it. Simplified meshes come from the
// data set's mesh store, so a reference is simplified once, ever.

#include "core/io/dataset.h"
#include "core/synthesis/simplified_mesh_store.h"
#include "render/walkthrough/gpu_panorama.h"

#include <condition_variable>
#include <deque>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <thread>

namespace triwalk {

class PanoramaCache {
public:
  // budgetBytes bounds the resident GPU panoramas, except that every
  // sample of the latest request stays resident (a frame draws from
  // them), however large they are. walkingScale > 0: simplified references
  // also get the walking mesh for frames at or below that scale
  // (preparePanorama).
  PanoramaCache(const Dataset& dataset, const WarpOptions& options, size_t budgetBytes, float walkingScale = 0.0f);
  ~PanoramaCache();
  PanoramaCache(const PanoramaCache&) = delete;
  PanoramaCache& operator=(const PanoramaCache&) = delete;

  // The samples wanted now, most wanted first (replaces earlier wishes):
  // every one a frame may draw, for none of them is evicted until the next
  // request.
  void request(std::span<const int> samples);
  // GL thread: the panorama if it is ready (uploading it if it was
  // prepared), else nullptr; never waits for the disk. Throws InputError
  // if the loader could not read it.
  const GpuPanorama* find(int sample);
  // GL thread: waits until the sample is loaded (offline rendering).
  const GpuPanorama* wait(int sample);
  // With simplified meshes: samples whose meshes the loader simplifies
  // into the data set's store while nothing is wanted (replaces the earlier
  // list), so that a first walk does not wait for meshoptimizer.
  void simplifyWhenIdle(std::span<const int> samples);

  struct Statistics {
    uint64_t hits = 0, misses = 0;
    size_t residentBytes = 0;
    int resident = 0;
    int pending = 0;  // wanted and not ready yet
    int meshesSimplified = 0, meshesRead = 0;  // simplified source meshes: made here, read from the store
  };
  Statistics statistics() const;

private:
  void loaderLoop();
  // Loader thread: the source's walking mesh, if it is to have one.
  std::optional<WalkingMesh> walkingMesh(const ViewRecord& view, const Panorama& panorama, const WarpSource& source);

  const Dataset& dataset_;
  WarpOptions options_;
  size_t budgetBytes_;
  float walkingScale_;
  SimplifiedMeshStore meshStore_;  // used by the loader thread; its counts are atomic

  mutable std::mutex mutex_;
  std::condition_variable wake_;      // loader: new wishes or stop
  std::condition_variable prepared_;  // GL thread: something was prepared
  std::deque<int> wanted_;
  std::deque<int> idleWork_;  // simplifyWhenIdle
  std::vector<int> pinned_;  // the latest request (what a frame may draw), never evicted
  std::map<int, std::shared_ptr<const PreparedPanorama>> ready_;
  std::map<int, std::string> failures_;
  std::set<int> residentSamples_;  // mirror of resident_ for the loader
  int loading_ = -1;
  bool stop_ = false;

  // GL thread only.
  std::map<int, std::unique_ptr<GpuPanorama>> resident_;
  std::list<int> recency_;  // most recent first
  size_t residentBytes_ = 0;
  uint64_t hits_ = 0, misses_ = 0;

  std::thread loader_;
};

}  // namespace triwalk
