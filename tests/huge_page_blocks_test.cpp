#include "core/support/huge_page_blocks.h"
#include "core/synthesis/warp_layer_cache.h"

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace triwalk;

namespace {

constexpr size_t kMiB = size_t(1) << 20;

void fill(void* block, size_t bytes, uint8_t value) {
  std::memset(block, value, bytes);
}

bool holds(const void* block, size_t bytes, uint8_t value) {
  const auto* p = static_cast<const uint8_t*>(block);
  for (size_t i = 0; i < bytes; ++i) {
    if (p[i] != value) return false;
  }
  return true;
}

// The kernel's transparent huge page setting: "always", "madvise" or
// "never" (the bracketed word), empty where the kernel has none.
std::string transparentHugePages() {
  std::ifstream file("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(file, line);
  const size_t open = line.find('['), close = line.find(']');
  return open == std::string::npos || close == std::string::npos ? "" : line.substr(open + 1, close - open - 1);
}

// The kibibytes of huge pages backing the mapping that holds address
// (from /proc/self/smaps).
size_t hugePageKibibytesAt(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  const auto target = reinterpret_cast<uintptr_t>(address);
  while (std::getline(smaps, line)) {
    uintptr_t from = 0, to = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> from >> dash >> to && dash == '-') {
      inside = from <= target && target < to;
      continue;
    }
    if (inside && line.rfind("AnonHugePages:", 0) == 0) return size_t(std::stoull(line.substr(14)));
  }
  return 0;
}

}  // namespace

TEST_CASE("huge-page blocks keep every block apart, reuse a freed block of its size and map in huge-page steps") {
  HugePageBlocks blocks(2 * kMiB);
  constexpr size_t kLayer = 100'000;  // 20 a mapping
  std::vector<void*> layers;
  for (int i = 0; i < 45; ++i) {
    layers.push_back(blocks.allocate(kLayer));
    CHECK(reinterpret_cast<uintptr_t>(layers.back()) % 64 == 0);
    fill(layers.back(), kLayer, uint8_t(i + 1));
  }
  CHECK(blocks.mappedBytes() == 3 * 2 * kMiB);
  CHECK(blocks.usedBytes() == 45 * 100'032);  // rounded up to 64 bytes
  for (int i = 0; i < 45; ++i) CHECK(holds(layers[size_t(i)], kLayer, uint8_t(i + 1)));

  // A freed block is the next of its size, and of no other size.
  blocks.free(layers[7], kLayer);
  void* other = blocks.allocate(kLayer / 2);
  CHECK(other != layers[7]);
  CHECK(blocks.allocate(kLayer) == layers[7]);
  blocks.free(other, kLayer / 2);
  CHECK(blocks.usedBytes() == 45 * 100'032);

  // A block larger than a mapping gets one of its own, in whole huge pages.
  const size_t mapped = blocks.mappedBytes();
  void* large = blocks.allocate(5 * kMiB);
  fill(large, 5 * kMiB, 0xAB);
  CHECK(blocks.mappedBytes() == mapped + 6 * kMiB);
  CHECK(holds(large, 5 * kMiB, 0xAB));
  for (int i = 0; i < 45; ++i) CHECK(holds(layers[size_t(i)], kLayer, uint8_t(i + 1)));
}

TEST_CASE("huge-page blocks hand free blocks' pages back to the kernel and reuse the faulted ones first") {
  HugePageBlocks blocks(8 * kMiB);
  std::vector<void*> held;
  for (int i = 0; i < 8; ++i) {
    held.push_back(blocks.allocate(kMiB));
    fill(held.back(), kMiB, 0x5A);
  }
  for (void* block : held) blocks.free(block, kMiB);
  CHECK(blocks.usedBytes() == 0);
  // The blocks are whole pages of a huge-page-aligned mapping: all of them
  // go back, and a block reused afterwards reads as the kernel's zeros,
  // not as what was written.
  CHECK(blocks.returnFreeToKernel() == 8 * kMiB);
  CHECK(blocks.returnFreeToKernel() == 0);
  void* returned = blocks.allocate(kMiB);
  CHECK(holds(returned, kMiB, 0));
  fill(returned, kMiB, 0x11);
  blocks.free(returned, kMiB);
  // The block whose pages are faulted in again comes before the others.
  CHECK(blocks.allocate(kMiB) == returned);
  CHECK(holds(returned, kMiB, 0x11));
  CHECK(blocks.mappedBytes() == 8 * kMiB);
}

TEST_CASE("huge-page blocks are backed by huge pages where the kernel gives them on advice") {
  const std::string setting = transparentHugePages();
  if (setting != "always" && setting != "madvise") {
    MESSAGE("this kernel gives no transparent huge pages on advice (setting '" << setting << "'): nothing to check");
    return;
  }
  HugePageBlocks blocks(4 * kMiB);
  void* block = blocks.allocate(4 * kMiB);
  fill(block, 4 * kMiB, 1);
  CHECK(hugePageKibibytesAt(block) >= 2048);
}

TEST_CASE("a cached layer's planes are one of the process's huge-page blocks, freed with the layer") {
  WarpLayer warped{
      ColorImage(8, 4), ScalarImage(8, 4, 2.5f), std::vector<uint8_t>(32, 1), 0, 0, {}, std::vector<float>(32, 0.75f)};
  warped.covered[5] = 0;
  for (size_t i = 0; i < 32; ++i) warped.color.pixels[i] = glm::vec3(0.5f, 0.25f, float(i));
  HugePageBlocks& blocks = HugePageBlocks::shared();
  const size_t before = blocks.usedBytes();
  {
    const CompactLayer layer(warped);
    CHECK(layer.bytes() == 5 * 32 * sizeof(uint16_t));
    CHECK(blocks.usedBytes() == before + 320);
    DecodedLayerRow row;
    layer.decodeRow(0, 32, row);
    CHECK(row.colorAt(31) == glm::vec3(0.5f, 0.25f, 31.0f));
    CHECK(row.distanceAt(4) == 2.5f);
    CHECK_FALSE(row.coveredAt(5));
    CHECK(row.reliabilityAt(7) == 0.75f);
  }
  CHECK(blocks.usedBytes() == before);
}
