// An allocator that starts each allocation at a different offset within a 4 KB page.
// Large arrays come from mmap and all start at the same page offset; the fifteen F and σ
// component arrays read side by side (particles.hpp) would then map every group's loads to
// the same L1 sets (and alias in the 4 KB store-forwarding check). Staggering the starts by
// 9 cache lines per allocation spreads them over all 64 sets.
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace latmpm::mpm {

template <class T>
struct StaggeredAllocator {
  using value_type = T;
  StaggeredAllocator() = default;
  template <class U>
  StaggeredAllocator(const StaggeredAllocator<U>&) {}

  T* allocate(size_t n) {
    static std::atomic<unsigned> counter{0};
    constexpr size_t line = 64, page = 4096;
    const size_t shift = line * (1 + (9 * counter.fetch_add(1, std::memory_order_relaxed)) % (page / line - 1));
    void* raw = std::malloc(n * sizeof(T) + page + line);
    if (!raw) throw std::bad_alloc();
    const uintptr_t aligned = (reinterpret_cast<uintptr_t>(raw) + line - 1) / line * line;
    T* out = reinterpret_cast<T*>(aligned + shift);
    reinterpret_cast<void**>(out)[-1] = raw;  // shift ≥ one line: room for the raw pointer
    return out;
  }
  void deallocate(T* p, size_t) { std::free(reinterpret_cast<void**>(p)[-1]); }

  template <class U>
  bool operator==(const StaggeredAllocator<U>&) const { return true; }
  template <class U>
  bool operator!=(const StaggeredAllocator<U>&) const { return false; }
};

}  // namespace latmpm::mpm
