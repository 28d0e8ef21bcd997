// Small SIMD value types (GCC/Clang vector extensions) and the few functions the solver's
// formulas need on them, so one templated formula serves plain Real and vectors:
//   Axes — x, y, z (and a spare lane) of one particle: shape-function stencils;
//   Pack — one value of eight particles: constitutive updates of a group of particles,
//          and the eight lanes of one grid node.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "mpm/real.hpp"

#if defined(__AVX__) || defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace latmpm::mpm {

typedef Real Axes __attribute__((vector_size(4 * sizeof(Real))));
typedef int32_t AxesInt __attribute__((vector_size(4 * sizeof(int32_t))));
typedef Real Pack __attribute__((vector_size(8 * sizeof(Real))));
inline constexpr int pack_width = 8;

namespace num {
// With AVX and Real = double, Axes is an __m256d: use the single instructions for these.
#if defined(__AVX__)
inline constexpr bool axes_are_m256d = std::is_same_v<Real, double>;
#else
inline constexpr bool axes_are_m256d = false;
#endif

inline Real max(Real a, Real b) { return std::max(a, b); }
inline Axes max(Axes a, Axes b) {
#if defined(__AVX__)
  if constexpr (axes_are_m256d) return (Axes)_mm256_max_pd((__m256d)a, (__m256d)b);
#endif
  return a > b ? a : b;
}
inline Real min(Real a, Real b) { return std::min(a, b); }
inline Axes min(Axes a, Axes b) {
#if defined(__AVX__)
  if constexpr (axes_are_m256d) return (Axes)_mm256_min_pd((__m256d)a, (__m256d)b);
#endif
  return a < b ? a : b;
}
inline Real abs(Real a) { return std::abs(a); }
inline Axes abs(Axes a) { return max(a, -a); }
inline Real clamp(Real a, Real lo, Real hi) { return std::clamp(a, lo, hi); }
inline Axes clamp(Axes a, Real lo, Real hi) { return min(max(a, Axes{} + lo), Axes{} + hi); }
inline Real log(Real a) { return std::log(a); }
inline Pack log(Pack a) {
  for (int q = 0; q < pack_width; ++q) a[q] = std::log(a[q]);
  return a;
}
// Largest integer ≤ x (as a floating-point value), and its conversion to int.
inline Real floor(Real x) { return std::floor(x); }
inline Axes floor(Axes x) {
#if defined(__AVX__)
  if constexpr (axes_are_m256d) return (Axes)_mm256_floor_pd((__m256d)x);
#endif
  for (int a = 0; a < 4; ++a) x[a] = std::floor(x[a]);
  return x;
}
inline int to_int(Real integral) { return static_cast<int>(integral); }
inline AxesInt to_int(Axes integral) { return __builtin_convertvector(integral, AxesInt); }
inline int floor_to_int(Real x) { return to_int(floor(x)); }
inline AxesInt floor_to_int(Axes x) { return to_int(floor(x)); }
inline Real to_real(int i) { return Real(i); }
inline Axes to_real(AxesInt i) { return __builtin_convertvector(i, Axes); }
template <class T>
inline T constant(Real c) {
  if constexpr (std::is_same_v<T, Real>) return c;
  else return T{} + c;
}

// The eight lanes of one grid node as a Pack: the grid's nodes are 64-byte aligned
// (sparse_grid.hpp). Loads and stores of Pack alias only Real, unlike the intrinsics' types,
// so the loops around them keep their indices in registers.
inline const Pack& node_pack(const Real* node) { return *reinterpret_cast<const Pack*>(node); }
inline Pack& node_pack(Real* node) { return *reinterpret_cast<Pack*>(node); }
// sum[q] = fma(c, node[q], sum[q]) for the eight lanes: one 512-bit fused multiply-add where
// the CPU has it; the same roundings as the lane loop.
inline Pack fma_node(Real c, const Real* node, Pack sum) {
#if defined(__AVX512F__)
  if constexpr (std::is_same_v<Real, double>)
    return (Pack)_mm512_fmadd_pd(_mm512_set1_pd(c), (__m512d)node_pack(node), (__m512d)sum);
#endif
  for (int q = 0; q < pack_width; ++q) sum[q] = std::fma(c, node[q], sum[q]);
  return sum;
}
// node[q] = fma(c, source[q], node[q]) for the lanes q whose bit is set in `lanes`, the others
// left as they are (bit for bit): one masked 512-bit fused multiply-add where the CPU has it.
inline void fma_into_node(Real* node, Real c, const Pack& source, unsigned lanes) {
#if defined(__AVX512F__)
  if constexpr (std::is_same_v<Real, double>) {
    Pack& target = node_pack(node);
    target = (Pack)_mm512_mask3_fmadd_pd(_mm512_set1_pd(c), (__m512d)source, (__m512d)target, __mmask8(lanes));
    return;
  }
#endif
  for (int q = 0; q < pack_width; ++q)
    if ((lanes >> q) & 1) node[q] = std::fma(c, source[q], node[q]);
}
}  // namespace num

}  // namespace latmpm::mpm
