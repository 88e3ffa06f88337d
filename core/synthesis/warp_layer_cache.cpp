#include "core/synthesis/warp_layer_cache.h"

#include "core/image/half_float.h"
#include "core/support/errors.h"
#include "core/support/huge_page_blocks.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

namespace triwalk {

namespace {

// The machine's memory (4 GiB where the system does not say).
size_t physicalMemoryBytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? size_t(pages) * size_t(pageSize) : size_t(4) << 30;
}

// Hands the pages the C library and the layers' blocks keep free back to
// the kernel, which does not count them available until then.
void returnFreePagesToKernel() {
  HugePageBlocks::shared().returnFreeToKernel();
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace

CompactLayer::CompactLayer(const WarpLayer& layer)
    : pixelCount_(layer.covered.size()),
      hasReliability_(!layer.reliability.empty()),
      halves_(static_cast<uint16_t*>(HugePageBlocks::shared().allocate(std::max<size_t>(bytes(), 1)))) {
  TRIWALK_CHECK(!hasReliability_ || layer.reliability.size() == pixelCount_, "a reliability for every pixel");
  uint16_t* const red = halves_;
  uint16_t* const green = red + pixelCount_;
  uint16_t* const blue = green + pixelCount_;
  uint16_t* const distance = blue + pixelCount_;
  // A chunk of pixels at a time, its planes in floats, then converted as
  // arrays (the processor's half instructions take eight at a time).
  constexpr size_t kChunk = 1024;
  float floats[4][kChunk];
  for (size_t first = 0; first < pixelCount_; first += kChunk) {
    const size_t count = std::min(kChunk, pixelCount_ - first);
    for (size_t k = 0; k < count; ++k) {
      const size_t i = first + k;
      const glm::vec3 color = layer.color.pixels[i];
      floats[0][k] = color.r;
      floats[1][k] = color.g;
      floats[2][k] = color.b;
      floats[3][k] = layer.covered[i] ? layer.distance.pixels[i] : std::numeric_limits<float>::quiet_NaN();
    }
    uint16_t* const planes[4] = {red, green, blue, distance};
    for (size_t p = 0; p < 4; ++p) floatsToHalves(std::span(floats[p], count), std::span(planes[p] + first, count));
  }
  if (hasReliability_) floatsToHalves(layer.reliability, std::span(halves_ + 4 * pixelCount_, pixelCount_));
}

CompactLayer::~CompactLayer() {
  HugePageBlocks::shared().free(halves_, std::max<size_t>(bytes(), 1));
}

void CompactLayer::decodeRow(size_t first, size_t count, DecodedLayerRow& row) const {
  TRIWALK_CHECK(first + count <= pixelCount_, "a row inside the layer");
  std::vector<float>* planes[4] = {&row.red, &row.green, &row.blue, &row.distance};
  for (size_t p = 0; p < 4; ++p) {
    planes[p]->resize(count);
    halvesToFloats(plane(p).subspan(first, count), *planes[p]);
  }
  row.reliability.resize(hasReliability_ ? count : 0);
  if (hasReliability_) halvesToFloats(plane(4).subspan(first, count), row.reliability);
}

size_t WarpLayerCache::bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}

size_t WarpLayerCache::budgetBytes() const {
  std::lock_guard lock(mutex_);
  return budgetBytes_;
}

void WarpLayerCache::setBudgetBytes(size_t budgetBytes) {
  std::lock_guard lock(mutex_);
  budgetBytes_ = budgetBytes;
  evictOverBudget();
}

void WarpLayerCache::evictOverBudget() {
  while (bytes_ > budgetBytes_ && recency_.size() > 1) {
    bytes_ -= recency_.back().second->bytes();
    index_.erase(recency_.back().first);
    evicted_.insert(recency_.back().first);
    recency_.pop_back();
  }
}

std::shared_ptr<const CompactLayer> WarpLayerCache::get(int source, int destination, const std::function<WarpLayer()>& make) {
  const Key key = (uint64_t(uint32_t(source)) << 32) | uint32_t(destination);
  {
    std::lock_guard lock(mutex_);
    const auto found = index_.find(key);
    if (found != index_.end()) {
      recency_.splice(recency_.begin(), recency_, found->second);
      ++hits_;
      return found->second->second;
    }
    ++misses_;
    missesAfterEviction_ += evicted_.erase(key);
  }
  auto layer = std::make_shared<const CompactLayer>(make());
  bool check = false;
  {
    std::lock_guard lock(mutex_);
    const auto found = index_.find(key);
    if (found != index_.end()) return found->second->second;  // another thread made it meanwhile
    recency_.emplace_front(key, layer);
    index_[key] = recency_.begin();
    bytes_ += layer->bytes();
    evictOverBudget();
    check = watch_.availableBytes && misses_ % kMissesBetweenChecks == 0;
  }
  if (check) checkMemory();
  return layer;
}

void WarpLayerCache::watchMemory(std::function<std::optional<size_t>()> availableBytes, size_t reserveBytes,
                                 size_t floorBytes) {
  std::lock_guard lock(mutex_);
  watch_ = {std::move(availableBytes), reserveBytes, floorBytes};
}

uint64_t WarpLayerCache::budgetCuts() const {
  std::lock_guard lock(mutex_);
  return budgetCuts_;
}

void WarpLayerCache::checkMemory() {
  MemoryWatch watch;
  {
    std::lock_guard lock(mutex_);
    watch = watch_;
  }
  const std::optional<size_t> available = watch.availableBytes();  // reads a file: outside the lock
  if (!available || *available >= watch.reserveBytes) return;
  {
    std::lock_guard lock(mutex_);
    const size_t shortfall = watch.reserveBytes - *available;
    const size_t lowered = std::max(bytes_ > shortfall ? bytes_ - shortfall : 0, watch.floorBytes);
    if (lowered >= budgetBytes_) return;
    budgetBytes_ = lowered;
    ++budgetCuts_;
    evictOverBudget();
  }
  // The dropped layers' pages go back to the kernel, not to the C
  // library's free lists, where the other process could not have them.
  returnFreePagesToKernel();
}

std::optional<size_t> availableMemoryBytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line)) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream fields(line.substr(13));
    size_t kibibytes = 0;
    if (fields >> kibibytes) return kibibytes * size_t(1024);
  }
  return std::nullopt;
}

size_t automaticLayerCacheBytes() {
  // Heap that earlier work in this process freed (another decimation, a
  // capture: bench, suite) is this process's to reuse, but the C library
  // keeps it, so the kernel does not count it available: handed back
  // first, a later decimation got 14.1 GiB, not 11.1 (docs/history/BENCHMARKS-2026-11.md).
  returnFreePagesToKernel();
  const size_t physical = physicalMemoryBytes();
  const size_t available = availableMemoryBytes().value_or(physical / 2);
  return std::max(std::min(available / 4 * 3, physical / 10 * 6), size_t(1) << 30);
}

void budgetByMachineMemory(WarpLayerCache& cache) {
  cache.setBudgetBytes(automaticLayerCacheBytes());
  const size_t physical = physicalMemoryBytes();
  constexpr size_t kFloor = size_t(256) << 20;
  cache.watchMemory(availableMemoryBytes, std::max(physical / 16, kFloor), kFloor);
}

}  // namespace triwalk
