#pragma once
// Blocks of one size each, carved from large anonymous mappings that the
// kernel is asked to back with transparent huge pages (2 MiB), for the
// warped-layer cache's layers: a decimation fills gigabytes of them, and
// with 4 KiB pages the kernel's page faults took a tenth of its CPU, more
// on a fresh virtual machine, whose memory the hypervisor backs on first
// touch (docs/history/BENCHMARKS-2026-11.md, "the layers' memory in huge pages"). The C
// library cannot be told to do this from inside the program, and a layer
// (a few hundred KiB) is too small for a huge page of its own, so blocks
// of a size share mappings and a freed block is kept for the next one of
// its size: memory the process faulted in once is reused without faults.
//
// Where the kernel has no transparent huge pages the mappings are plain
// pages; everything else is the same.

#include <cstddef>
#include <map>
#include <mutex>
#include <vector>

namespace triwalk {

class HugePageBlocks {
public:
  // The blocks of the whole process (the layers of every cache).
  static HugePageBlocks& shared();

  explicit HugePageBlocks(size_t mappingBytes = kMappingBytes);
  ~HugePageBlocks();
  HugePageBlocks(const HugePageBlocks&) = delete;
  HugePageBlocks& operator=(const HugePageBlocks&) = delete;

  // A block of `bytes` (> 0), aligned to 64 bytes; its contents are
  // unspecified. Throws std::bad_alloc when the kernel refuses a mapping.
  void* allocate(size_t bytes);
  // A block allocate(bytes) gave, with the same bytes.
  void free(void* block, size_t bytes);
  // Hands the memory of every free block back to the kernel (it stays
  // mapped and is faulted in again when reused), so that the machine's
  // available memory counts it: what malloc_trim does for the C library's
  // free lists. Returns the bytes handed back.
  size_t returnFreeToKernel();

  // Bytes mapped, and bytes in blocks given out and not freed.
  size_t mappedBytes() const;
  size_t usedBytes() const;

  static constexpr size_t kHugePageBytes = size_t(2) << 20;
  static constexpr size_t kMappingBytes = size_t(32) << 20;

private:
  struct SizeClass {
    size_t blockBytes = 0;  // the size asked for, rounded up to 64 bytes
    std::vector<void*> free;
    std::vector<void*> returned;  // free, their pages handed back to the kernel
    char* next = nullptr;         // the unused rest of the newest mapping
    char* end = nullptr;
  };

  void mapAnother(SizeClass& sizeClass);

  size_t mappingBytes_;
  mutable std::mutex mutex_;
  std::map<size_t, SizeClass> classes_;  // by the bytes asked for
  std::vector<std::pair<void*, size_t>> mappings_;
  size_t mappedBytes_ = 0, usedBytes_ = 0;
};

}  // namespace triwalk
