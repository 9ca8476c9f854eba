#pragma once
/// \brief Storage for large arrays read at scattered places, such as a point light's cube map.
#include <cstddef>
#include <memory>
#include <type_traits>

namespace shadowkit {

/// The size of a transparent huge page on x86-64.
inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;

struct HugePagesFree {
  void operator()(void* p) const;
};

/// An array from make_huge_page_array.
template <class T>
using HugePageArray = std::unique_ptr<T[], HugePagesFree>;

/// Uninitialized room for \p bytes. At least a huge page of it is aligned to one and advised
/// for transparent huge pages (madvise MADV_HUGEPAGE): a lookup pass over a 100 MB cube map
/// then misses the TLB far less, and its first touch faults once per 2 MiB, not per 4 KiB.
/// Less is an ordinary allocation. Throws std::bad_alloc when the memory is not there.
void* allocate_huge_pages(std::size_t bytes);

/// Uninitialized room for \p n values of \p T: only the pages written take memory.
template <class T>
HugePageArray<T> make_huge_page_array(std::size_t n) {
  static_assert(std::is_trivially_default_constructible_v<T> &&
                std::is_trivially_destructible_v<T>);
  return HugePageArray<T>(static_cast<T*>(allocate_huge_pages(n * sizeof(T))));
}

}  // namespace shadowkit
