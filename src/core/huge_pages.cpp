#include "shadowkit/core/huge_pages.h"

#include <sys/mman.h>

#include <cstdlib>
#include <new>

namespace shadowkit {

void HugePagesFree::operator()(void* p) const {
  std::free(p);
}

void* allocate_huge_pages(std::size_t bytes) {
  if (bytes < kHugePageBytes) {
    if (void* p = std::malloc(bytes == 0 ? 1 : bytes)) return p;
    throw std::bad_alloc();
  }
  const std::size_t rounded = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
  void* p = std::aligned_alloc(kHugePageBytes, rounded);
  if (!p) throw std::bad_alloc();
  // Only advice: where the kernel has transparent huge pages off, the pages stay small.
  madvise(p, rounded, MADV_HUGEPAGE);
  return p;
}

}  // namespace shadowkit
