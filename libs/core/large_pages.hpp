// Memory for large arrays read out of order, on 2 MB pages where the kernel allows it.
//
// The solver's grid lanes, DDMP's nodal values and its distribution coefficients are tens of
// MB read block by block in an order of their own (a block of 64 nodes is one 4 kB page of
// lanes, and a smoothing halo touches 27 of them): on 4 kB pages nearly every block costs a
// TLB miss and a page walk. Linux backs memory with 2 MB pages ("transparent huge pages")
// when a region asks for it with madvise(MADV_HUGEPAGE), the setting Debian ships
// (/sys/kernel/mm/transparent_hugepage/enabled = madvise). Measured: QUICK T2P30 under DDMP
// with every allocation on such pages (glibc's malloc tunable) took ≈ 9 % less CPU
// (docs/benchmarks.md, 2026-11-29). Where the kernel says no, the advice is ignored and the
// memory is ordinary: the same values, the same bits.
#pragma once
#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <new>

namespace latmpm {

inline constexpr size_t large_page_bytes = size_t(2) << 20;
// Below this an allocation is not worth a page of its own (it would waste up to 2 MB).
inline constexpr size_t large_page_threshold = size_t(4) << 20;

// Allocates `bytes` aligned to a cache line; from `large_page_threshold` up, aligned to and
// rounded up to whole large pages, advised to use them.
inline void* allocate_on_large_pages(size_t bytes) {
  const bool large = bytes >= large_page_threshold;
  const size_t align = large ? large_page_bytes : 64;
  const size_t rounded = (bytes + align - 1) / align * align;
  void* p = std::aligned_alloc(align, rounded == 0 ? align : rounded);
  if (!p) throw std::bad_alloc();
  if (large) madvise(p, rounded, MADV_HUGEPAGE);  // advice only: failure leaves ordinary pages
  return p;
}

// A std allocator on allocate_on_large_pages (cache-line aligned below the threshold, as
// tbb::cache_aligned_allocator, which it replaces for the grid's lanes).
template <class T>
struct LargePageAllocator {
  using value_type = T;
  LargePageAllocator() = default;
  template <class U>
  LargePageAllocator(const LargePageAllocator<U>&) {}
  T* allocate(size_t n) {
    if (n > size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocate_on_large_pages(n * sizeof(T)));
  }
  void deallocate(T* p, size_t) { std::free(p); }
  template <class U>
  bool operator==(const LargePageAllocator<U>&) const {
    return true;
  }
  template <class U>
  bool operator!=(const LargePageAllocator<U>&) const {
    return false;
  }
};

}  // namespace latmpm
