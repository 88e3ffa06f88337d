#include "core/support/huge_page_memory.h"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <new>

namespace triwalk {
namespace {

size_t roundUp(size_t value, size_t multiple) { return (value + multiple - 1) / multiple * multiple; }

size_t mappedLength(size_t bytes) { return roundUp(std::max<size_t>(bytes, 1), size_t(::sysconf(_SC_PAGE_SIZE))); }

}  // namespace

void* HugePageResource::do_allocate(size_t bytes, size_t alignment) {
  if (alignment > kHugePageBytes) throw std::bad_alloc();
  // Map 2 MiB more than needed and unmap both ends, so the kernel can
  // back every whole 2 MiB of the rest with a huge page.
  const size_t length = mappedLength(bytes);
  void* mapped = ::mmap(nullptr, length + kHugePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  const uintptr_t start = reinterpret_cast<uintptr_t>(mapped);
  const uintptr_t aligned = roundUp(start, kHugePageBytes);
  const uintptr_t end = start + length + kHugePageBytes;
  if (aligned > start) ::munmap(mapped, aligned - start);
  if (end > aligned + length) ::munmap(reinterpret_cast<void*>(aligned + length), end - (aligned + length));
  // Only a hint: without transparent huge pages the memory is as good.
  ::madvise(reinterpret_cast<void*>(aligned), length, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(aligned);
}

void HugePageResource::do_deallocate(void* pointer, size_t bytes, size_t) { ::munmap(pointer, mappedLength(bytes)); }

HugePagePool::HugePagePool(size_t blockBytes, size_t chunkBytes)
    : pool_(std::pmr::pool_options{.max_blocks_per_chunk = std::max<size_t>(1, chunkBytes / std::max<size_t>(blockBytes, 1)),
                                   .largest_required_pool_block = blockBytes},
            &hugePages_) {}

}  // namespace triwalk
