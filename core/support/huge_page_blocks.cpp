#include "core/support/huge_page_blocks.h"

#include "core/support/errors.h"

#include <sanitizer/asan_interface.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <new>

namespace triwalk {

namespace {

constexpr size_t kBlockAlignment = 64;

size_t roundUp(size_t value, size_t multiple) {
  return (value + multiple - 1) / multiple * multiple;
}

size_t pageBytes() {
  const long page = ::sysconf(_SC_PAGE_SIZE);
  return page > 0 ? size_t(page) : 4096;
}

}  // namespace

HugePageBlocks& HugePageBlocks::shared() {
  // Never destroyed: a layer that outlives main (held by another static)
  // still has blocks to go back to. The kernel takes the mappings at exit.
  static HugePageBlocks* const blocks = new HugePageBlocks;
  return *blocks;
}

HugePageBlocks::HugePageBlocks(size_t mappingBytes) : mappingBytes_(roundUp(mappingBytes, kHugePageBytes)) {}

HugePageBlocks::~HugePageBlocks() {
  for (const auto& [address, bytes] : mappings_) {
    ASAN_UNPOISON_MEMORY_REGION(address, bytes);  // the addresses may be mapped again by others
    ::munmap(address, bytes);
  }
}

void HugePageBlocks::mapAnother(SizeClass& sizeClass) {
  // A block larger than a mapping gets a mapping of its own.
  const size_t bytes = std::max(mappingBytes_, roundUp(sizeClass.blockBytes, kHugePageBytes));
  // Mapped with a huge page's slack, so that the mapping's start can be
  // moved to a huge page boundary: the kernel backs only aligned 2 MiB
  // ranges with huge pages.
  void* mapped = ::mmap(nullptr, bytes + kHugePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  char* const start = reinterpret_cast<char*>(mapped);
  char* const aligned = reinterpret_cast<char*>(roundUp(reinterpret_cast<uintptr_t>(start), kHugePageBytes));
  if (aligned > start) ::munmap(start, size_t(aligned - start));
  const size_t tail = size_t(start + bytes + kHugePageBytes - (aligned + bytes));
  if (tail > 0) ::munmap(aligned + bytes, tail);
#ifdef MADV_HUGEPAGE
  // Advice only: where the kernel has no huge pages the mapping stays as it is.
  ::madvise(aligned, bytes, MADV_HUGEPAGE);
#endif
  // Under AddressSanitizer a block is addressable only while it is given
  // out, so that a layer read past its end or after it was freed is still
  // caught as with the C library's blocks (no-ops in other builds).
  ASAN_POISON_MEMORY_REGION(aligned, bytes);
  mappings_.emplace_back(aligned, bytes);
  mappedBytes_ += bytes;
  sizeClass.next = aligned;
  sizeClass.end = aligned + bytes;
}

void* HugePageBlocks::allocate(size_t bytes) {
  TRIWALK_CHECK(bytes > 0, "a block of at least one byte");
  std::lock_guard lock(mutex_);
  SizeClass& sizeClass = classes_[bytes];
  if (sizeClass.blockBytes == 0) sizeClass.blockBytes = roundUp(bytes, kBlockAlignment);
  // A freed block whose pages are still faulted in first, then one whose
  // pages went back to the kernel, then a fresh one.
  void* block = nullptr;
  for (std::vector<void*>* list : {&sizeClass.free, &sizeClass.returned}) {
    if (block != nullptr || list->empty()) continue;
    block = list->back();
    list->pop_back();
  }
  if (block == nullptr) {
    if (size_t(sizeClass.end - sizeClass.next) < sizeClass.blockBytes) mapAnother(sizeClass);
    block = sizeClass.next;
    sizeClass.next += sizeClass.blockBytes;
  }
  ASAN_UNPOISON_MEMORY_REGION(block, bytes);
  usedBytes_ += sizeClass.blockBytes;  // only once the block is given: mapAnother may throw
  return block;
}

void HugePageBlocks::free(void* block, size_t bytes) {
  if (block == nullptr) return;
  std::lock_guard lock(mutex_);
  const auto found = classes_.find(bytes);
  TRIWALK_CHECK(found != classes_.end(), "a block freed with the size it was allocated with");
  ASAN_POISON_MEMORY_REGION(block, bytes);
  found->second.free.push_back(block);
  usedBytes_ -= found->second.blockBytes;
}

size_t HugePageBlocks::returnFreeToKernel() {
  const size_t page = pageBytes();
  std::lock_guard lock(mutex_);
  size_t returned = 0;
  for (auto& [bytes, sizeClass] : classes_) {
    for (void* block : sizeClass.free) {
      // The whole pages inside the block: its neighbours may be in use.
      const uintptr_t first = roundUp(reinterpret_cast<uintptr_t>(block), page);
      const uintptr_t last = (reinterpret_cast<uintptr_t>(block) + sizeClass.blockBytes) / page * page;
      if (last > first && ::madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED) == 0) {
        returned += last - first;
      }
      sizeClass.returned.push_back(block);
    }
    sizeClass.free.clear();
  }
  return returned;
}

size_t HugePageBlocks::mappedBytes() const {
  std::lock_guard lock(mutex_);
  return mappedBytes_;
}

size_t HugePageBlocks::usedBytes() const {
  std::lock_guard lock(mutex_);
  return usedBytes_;
}

}  // namespace triwalk
