#pragma once
// Memory the kernel may back with transparent huge pages (2 MiB). For the
// warped-layer cache: it fills gigabytes of fresh memory, and on a
// virtual machine each first touch of a 4 KiB page is a costly fault
// (docs/BENCHMARKS.md, "huge pages for the warped-layer cache"). Where the
// kernel has transparent huge pages off, this is plain anonymous memory.

#include <cstddef>
#include <memory_resource>

namespace triwalk {

inline constexpr size_t kHugePageBytes = size_t(2) << 20;

// Each allocation is its own mapping, aligned to 2 MiB and marked
// MADV_HUGEPAGE, unmapped when deallocated: meant as the upstream of a
// pool that asks for large chunks and keeps them.
class HugePageResource final : public std::pmr::memory_resource {
private:
  void* do_allocate(size_t bytes, size_t alignment) override;
  void do_deallocate(void* pointer, size_t bytes, size_t alignment) override;
  bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override { return this == &other; }
};

// A thread-safe pool of equal blocks of blockBytes (smaller requests are
// pooled too) carved from huge-page chunks of about chunkBytes. Blocks are
// reused, never returned to the kernel before the pool is destroyed, so the
// pool's memory is its peak use.
class HugePagePool {
public:
  HugePagePool(size_t blockBytes, size_t chunkBytes);
  std::pmr::memory_resource* resource() { return &pool_; }

private:
  HugePageResource hugePages_;
  std::pmr::synchronized_pool_resource pool_;
};

}  // namespace triwalk
