#include "render/walkthrough/panorama_cache.h"

#include "core/support/errors.h"

#include <algorithm>
#include <optional>

namespace triwalk {

PanoramaCache::PanoramaCache(const Dataset& dataset, const WarpOptions& options, size_t budgetBytes, float walkingScale)
    : dataset_(dataset),
      options_(options),
      budgetBytes_(budgetBytes),
      walkingScale_(walkingScale),
      meshStore_(dataset),
      loader_([this] { loaderLoop(); }) {}

PanoramaCache::~PanoramaCache() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  loader_.join();
}

void PanoramaCache::request(std::span<const int> samples) {
  {
    std::lock_guard lock(mutex_);
    wanted_.assign(samples.begin(), samples.end());
    pinned_.assign(samples.begin(), samples.end());
  }
  wake_.notify_all();
}

void PanoramaCache::simplifyWhenIdle(std::span<const int> samples) {
  if (options_.mesh != SourceMesh::Simplified) return;
  {
    std::lock_guard lock(mutex_);
    idleWork_.assign(samples.begin(), samples.end());
  }
  wake_.notify_all();
}

void PanoramaCache::loaderLoop() {
  std::unique_lock lock(mutex_);
  const auto unloaded = [&](int s) { return !ready_.count(s) && !failures_.count(s) && !residentSamples_.count(s); };
  while (true) {
    const auto work = [&] { return !idleWork_.empty() || std::any_of(wanted_.begin(), wanted_.end(), unloaded); };
    wake_.wait(lock, [&] { return stop_ || work(); });
    if (stop_) return;
    const auto next = std::find_if(wanted_.begin(), wanted_.end(), unloaded);
    if (next == wanted_.end()) {
      // Idle: simplify one mesh (and its walking mesh) into the store (a
      // failure to read shows when the sample is wanted). A sample loaded
      // already went through the store.
      const int sample = idleWork_.front();
      idleWork_.pop_front();
      if (!unloaded(sample)) continue;
      lock.unlock();
      try {
        const ViewRecord& view = dataset_.sample(sample);
        const Panorama panorama = dataset_.loadView(view);
        const WarpSource source = meshStore_.source(view, panorama, options_);
        walkingMesh(view, panorama, source);
      } catch (const std::exception&) {
      }
      lock.lock();
      continue;
    }
    const int sample = *next;
    loading_ = sample;
    lock.unlock();
    std::shared_ptr<const PreparedPanorama> prepared;
    std::string failure;
    try {
      const ViewRecord& view = dataset_.sample(sample);
      const Panorama panorama = dataset_.loadView(view);
      const WarpSource source = meshStore_.source(view, panorama, options_);
      const std::optional<WalkingMesh> walking = walkingMesh(view, panorama, source);
      prepared = std::make_shared<const PreparedPanorama>(
          preparePanorama(panorama, degreesToRadians(view.yawDegrees), source, walking ? &*walking : nullptr));
    } catch (const std::exception& error) {
      failure = error.what();
    }
    lock.lock();
    loading_ = -1;
    if (prepared) {
      ready_[sample] = std::move(prepared);
    } else {
      failures_[sample] = failure;
    }
    prepared_.notify_all();
  }
}

std::optional<WalkingMesh> PanoramaCache::walkingMesh(const ViewRecord& view, const Panorama& panorama,
                                                      const WarpSource& source) {
  if (walkingScale_ <= 0.0f || source.mesh() != SourceMesh::Simplified) return std::nullopt;
  return WalkingMesh{meshStore_.walkingTriangles(view, panorama, source, options_, walkingScale_), walkingScale_};
}

const GpuPanorama* PanoramaCache::find(int sample) {
  const auto resident = resident_.find(sample);
  if (resident != resident_.end()) {
    recency_.remove(sample);
    recency_.push_front(sample);
    ++hits_;
    return resident->second.get();
  }
  std::shared_ptr<const PreparedPanorama> prepared;
  std::vector<int> pinned;
  {
    std::lock_guard lock(mutex_);
    const auto failure = failures_.find(sample);
    if (failure != failures_.end()) throw InputError(dataset_.sample(sample).file, failure->second);
    const auto ready = ready_.find(sample);
    if (ready == ready_.end()) {
      ++misses_;
      if (std::find(wanted_.begin(), wanted_.end(), sample) == wanted_.end()) wanted_.push_front(sample);
      wake_.notify_all();
      return nullptr;
    }
    prepared = ready->second;
    ready_.erase(ready);
    pinned = pinned_;
  }
  ++hits_;
  auto panorama = std::make_unique<GpuPanorama>(*prepared);
  residentBytes_ += panorama->bytes();
  const GpuPanorama* result = panorama.get();
  resident_[sample] = std::move(panorama);
  recency_.push_front(sample);
  std::vector<int> evicted;
  // Evict the least recently used, never one the current frame may draw
  // (its triangle's and the neighbours' for its holes, all requested): a
  // frame holds their pointers until it is drawn. Pinning only the
  // triangle's three let a neighbour loaded later evict one loaded before
  // when six references did not fit the budget (4096-pixel captures under
  // the default 1 GiB), and the frame drew from freed memory.
  for (auto it = recency_.end(); residentBytes_ > budgetBytes_ && it != recency_.begin();) {
    --it;
    if (*it == sample || std::find(pinned.begin(), pinned.end(), *it) != pinned.end()) continue;
    residentBytes_ -= resident_.at(*it)->bytes();
    resident_.erase(*it);
    evicted.push_back(*it);
    it = recency_.erase(it);
  }
  std::lock_guard lock(mutex_);
  residentSamples_.insert(sample);
  for (int s : evicted) residentSamples_.erase(s);
  return result;
}

const GpuPanorama* PanoramaCache::wait(int sample) {
  while (true) {
    if (const GpuPanorama* panorama = find(sample)) return panorama;
    std::unique_lock lock(mutex_);
    prepared_.wait(lock, [&] { return ready_.count(sample) || failures_.count(sample); });
  }
}

PanoramaCache::Statistics PanoramaCache::statistics() const {
  Statistics statistics;
  statistics.hits = hits_;
  statistics.misses = misses_;
  statistics.residentBytes = residentBytes_;
  statistics.resident = int(resident_.size());
  statistics.meshesSimplified = meshStore_.simplified();
  statistics.meshesRead = meshStore_.loaded();
  std::lock_guard lock(mutex_);
  for (int s : wanted_) statistics.pending += !residentSamples_.count(s);
  return statistics;
}

}  // namespace triwalk
