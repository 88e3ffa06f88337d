// The warped-layer cache's memory: huge-page mappings (the kernel's
// MADV_HUGEPAGE flag, read back from /proc/self/smaps), pooled in equal
// blocks, and layers that read back what the warp computed.

#include "core/support/huge_page_memory.h"
#include "core/synthesis/warp_layer_cache.h"
#include "tests/analytic_scene.h"

#include <doctest/doctest.h>

#include <Imath/half.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

using namespace triwalk;

namespace {

// The mapping of this process that holds address, as /proc/self/smaps
// lists it: its start and whether its VmFlags carry "hg" (MADV_HUGEPAGE).
struct Mapping {
  uintptr_t start = 0;
  bool hugePageAdvice = false;
};

Mapping mappingOf(const void* address) {
  const uintptr_t at = reinterpret_cast<uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  REQUIRE(smaps);
  std::string line;
  bool inside = false;
  Mapping mapping;
  while (std::getline(smaps, line)) {
    uintptr_t start = 0, end = 0;
    char dash = 0;
    std::istringstream header(line);
    if (header >> std::hex >> start >> dash >> end && dash == '-' && line.find(':') > line.find(' ')) {
      inside = start <= at && at < end;
      if (inside) mapping.start = start;
      continue;
    }
    if (inside && line.starts_with("VmFlags:")) {
      std::istringstream flags(line.substr(8));
      std::string flag;
      while (flags >> flag) mapping.hugePageAdvice |= flag == "hg";
      return mapping;
    }
  }
  FAIL("no mapping in /proc/self/smaps holds the address");
  return mapping;
}

}  // namespace

TEST_CASE("huge-page memory is aligned to 2 MiB, usable to its last byte, and advised for huge pages") {
  HugePageResource resource;
  for (const size_t bytes : {size_t(1), size_t(327680), kHugePageBytes, size_t(5) * kHugePageBytes + 12345}) {
    CAPTURE(bytes);
    void* memory = resource.allocate(bytes, 64);
    CHECK(reinterpret_cast<uintptr_t>(memory) % kHugePageBytes == 0);
    std::memset(memory, 0x5a, bytes);
    CHECK(static_cast<unsigned char*>(memory)[bytes - 1] == 0x5a);
    const Mapping mapping = mappingOf(memory);
    CHECK(mapping.hugePageAdvice);
    CHECK(mapping.start == reinterpret_cast<uintptr_t>(memory));
    resource.deallocate(memory, bytes, 64);
  }
}

TEST_CASE("the layer pool hands out blocks from a few huge-page chunks and reuses freed blocks") {
  constexpr size_t kBlock = 327680;  // a 256x128 layer with its reliability
  HugePagePool pool(kBlock, size_t(32) << 20);
  std::vector<void*> blocks;
  std::set<uintptr_t> chunks;
  for (int i = 0; i < 200; ++i) {
    blocks.push_back(pool.resource()->allocate(kBlock, alignof(Imath::half)));
    const Mapping mapping = mappingOf(blocks.back());
    CHECK(mapping.hugePageAdvice);
    chunks.insert(mapping.start);
  }
  // 200 blocks of 320 KiB in chunks of up to 32 MiB: a handful of mappings,
  // not one per block.
  CHECK(chunks.size() <= 8);
  const std::set<void*> given(blocks.begin(), blocks.end());
  CHECK(given.size() == blocks.size());
  for (void* block : blocks) pool.resource()->deallocate(block, kBlock, alignof(Imath::half));
  void* again = pool.resource()->allocate(kBlock, alignof(Imath::half));
  CHECK(given.contains(again));
  pool.resource()->deallocate(again, kBlock, alignof(Imath::half));
}

TEST_CASE("a compact layer reads back the warped layer in half floats, reliability included") {
  const testing::AnalyticScene scene = testing::stripedRoom();
  const Panorama source = testing::renderPanorama(scene, {0.0f, 0.0f, 1.5f}, 128);
  const WarpSource warpSource(source, {0.0f, 0.0f, 1.5f}, 0.0f, WarpOptions{});
  const DestinationCamera camera = DestinationCamera::panorama({0.6f, -0.3f, 1.5f}, 128, 64);
  for (const LayerReliability reliability : {LayerReliability::Computed, LayerReliability::Omitted}) {
    const WarpLayer layer = warpToCamera(warpSource, camera, WarpMethod::Mesh, reliability);
    const size_t pixels = layer.covered.size();
    HugePagePool pool(CompactLayer::bytesFor(pixels, reliability), size_t(32) << 20);
    const CompactLayer compact(layer, pool.resource());
    CHECK(compact.bytes() == CompactLayer::bytesFor(pixels, reliability));
    size_t covered = 0;
    for (size_t i = 0; i < pixels; ++i) {
      CAPTURE(i);
      REQUIRE(compact.coveredAt(i) == layer.coveredAt(i));
      if (!layer.coveredAt(i)) continue;
      ++covered;
      CHECK(compact.distanceAt(i) == float(Imath::half(layer.distanceAt(i))));
      CHECK(compact.colorAt(i).g == float(Imath::half(layer.colorAt(i).g)));
      CHECK(compact.reliabilityAt(i) == (reliability == LayerReliability::Computed
                                             ? float(Imath::half(layer.reliabilityAt(i)))
                                             : 1.0f));
    }
    CHECK(covered > pixels * 9 / 10);
  }
}
