// Small SIMD value types (GCC/Clang vector extensions) and the few functions the solver's
// formulas need on them, so one templated formula serves plain Real and vectors:
//   Axes — x, y, z (and a spare lane) of one particle: shape-function stencils;
//   Pack — one value of eight particles: constitutive updates of a group of particles,
//          and the eight lanes of one grid node.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "mpm/real.hpp"

#if defined(__AVX__) || defined(__AVX512F__)
#include <immintrin.h>
#endif

namespace latmpm::mpm {

typedef Real Axes __attribute__((vector_size(4 * sizeof(Real))));
typedef int32_t AxesInt __attribute__((vector_size(4 * sizeof(int32_t))));
typedef Real Pack __attribute__((vector_size(8 * sizeof(Real))));
typedef Real Duo __attribute__((vector_size(2 * sizeof(Real))));  // two neighbouring values
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

// A Pack's lanes 0–3 and 4–7 as Axes, and back.
inline Axes low_half(const Pack& p) { return __builtin_shufflevector(p, p, 0, 1, 2, 3); }
inline Axes high_half(const Pack& p) { return __builtin_shufflevector(p, p, 4, 5, 6, 7); }
inline Pack join_halves(const Axes& low, const Axes& high) {
  return __builtin_shufflevector(low, high, 0, 1, 2, 3, 4, 5, 6, 7);
}
// A vector of consecutive values at any address (unaligned load and store).
template <class V>
inline V load(const Real* at) {
  V v;
  std::memcpy(&v, at, sizeof v);
  return v;
}
template <class V>
inline void store(Real* at, const V& v) { std::memcpy(at, &v, sizeof v); }
// Whether a Pack is two native four-lane halves (AVX without AVX-512): there GCC 12 builds any
// eight-lane value it cannot keep in registers (a splat of a scalar, a sum carried through a
// call) on the stack, read back in 16-byte pieces with a store-forwarding stall each, so the
// hot loops work on the halves (node_lanes.hpp, NodeSum, MaskedLanes; docs/benchmarks.md,
// "Eight-lane splats on AVX2").
#if defined(__AVX__) && !defined(__AVX512F__)
inline constexpr bool pack_in_halves = true;
#else
inline constexpr bool pack_in_halves = false;
#endif

// The eight lanes of one grid node as a Pack: the grid's nodes are 64-byte aligned
// (sparse_grid.hpp). Loads and stores of Pack alias only Real, unlike the intrinsics' types,
// so the loops around them keep their indices in registers.
inline const Pack& node_pack(const Real* node) { return *reinterpret_cast<const Pack*>(node); }
inline Pack& node_pack(Real* node) { return *reinterpret_cast<Pack*>(node); }

// Σ c_i node_i over whole nodes, lane by lane, one fused multiply-add per lane and node (the
// same roundings as a lane loop of std::fma): add(c, node) adds c times the node's eight lanes.
// Kept in one 512-bit register with AVX-512 and in two 256-bit ones with AVX2.
//
// MaskedLanes: a source node's lanes added into other nodes, c times each: add_into(node, c)
// sets node[q] = fma(c, source[q], node[q]) for the lanes q whose bit is set in `lanes` and
// leaves the others as they are (bit for bit). The source and its mask are laid out once, so
// each receiver costs one masked 512-bit fused multiply-add (AVX-512) or two 256-bit ones
// blended by the mask (AVX2).
//
// Halves (a template argument of add and add_into; bit 0 lanes 0–3, bit 1 lanes 4–7): the
// halves of the node that take part. With AVX2 the others cost nothing: NodeSum leaves them
// out of the sum (its lanes there are then not meaningful), add_into must be given every half
// with a lane of its mask (MaskedLanes::halves()). The other builds work on whole nodes.
inline constexpr unsigned both_halves = 3, low_lanes = 1, high_lanes = 2;
#if defined(__AVX512F__)
struct NodeSum {
  Pack lanes{};
  template <unsigned Halves = both_halves>
  void add(Real c, const Real* node) {
    lanes = (Pack)_mm512_fmadd_pd(_mm512_set1_pd(c), (__m512d)node_pack(node), (__m512d)lanes);
  }
  Real operator[](int q) const { return lanes[q]; }
};
class MaskedLanes {
 public:
  MaskedLanes(const Pack& source, unsigned lanes) : source_(source), mask_(__mmask8(lanes)) {}
  unsigned halves() const { return ((mask_ & 15) ? low_lanes : 0) | ((mask_ >> 4) ? high_lanes : 0); }
  template <unsigned Halves = both_halves>
  void add_into(Real* node, Real c) const {
    Pack& target = node_pack(node);
    target = (Pack)_mm512_mask3_fmadd_pd(_mm512_set1_pd(c), (__m512d)source_, (__m512d)target, mask_);
  }

 private:
  Pack source_;
  __mmask8 mask_;
};
#elif defined(__AVX2__) && defined(__FMA__)
struct NodeSum {
  __m256d low = _mm256_setzero_pd(), high = _mm256_setzero_pd();
  template <unsigned Halves = both_halves>
  void add(Real c, const Real* node) {
    const __m256d copies = _mm256_set1_pd(c);
    if constexpr ((Halves & low_lanes) != 0) low = _mm256_fmadd_pd(copies, _mm256_loadu_pd(node), low);
    if constexpr ((Halves & high_lanes) != 0) high = _mm256_fmadd_pd(copies, _mm256_loadu_pd(node + 4), high);
  }
  Real operator[](int q) const { return q < 4 ? ((Axes)low)[q] : ((Axes)high)[q - 4]; }
};
class MaskedLanes {
 public:
  MaskedLanes(const Pack& source, unsigned lanes)
      : source_{(__m256d)low_half(source), (__m256d)high_half(source)},
        mask_{half_mask(lanes & 15), half_mask((lanes >> 4) & 15)},
        halves_(((lanes & 15) ? low_lanes : 0) | ((lanes >> 4) ? high_lanes : 0)) {}
  unsigned halves() const { return halves_; }
  // `node` is a grid node (64-byte aligned). Its halves are read and written as Axes, which
  // alias only Real: with the intrinsics' own loads and stores (which alias anything) the
  // hand-on's loop reloaded its share count and the grid's base pointer at every share.
  template <unsigned Halves = both_halves>
  void add_into(Real* node, Real c) const {
    const __m256d copies = _mm256_set1_pd(c);
    for (int h = 0; h < 2; ++h) {
      if (((Halves >> h) & 1) == 0) continue;
      Axes& half = *reinterpret_cast<Axes*>(node + 4 * h);
      const __m256d target = (__m256d)half;
      half = (Axes)_mm256_blendv_pd(target, _mm256_fmadd_pd(copies, source_[h], target), mask_[h]);
    }
  }

 private:
  static __m256d half_mask(unsigned bits) {  // lane q all ones where bit q is set
    const __m256i each = _mm256_setr_epi64x(1, 2, 4, 8);
    return _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(_mm256_set1_epi64x(bits), each), each));
  }
  __m256d source_[2], mask_[2];
  unsigned halves_;
};
#else
struct NodeSum {
  Pack lanes{};
  template <unsigned Halves = both_halves>
  void add(Real c, const Real* node) {
    for (int q = 0; q < pack_width; ++q) lanes[q] = std::fma(c, node[q], lanes[q]);
  }
  Real operator[](int q) const { return lanes[q]; }
};
class MaskedLanes {
 public:
  MaskedLanes(const Pack& source, unsigned lanes) : source_(source), lanes_(lanes) {}
  unsigned halves() const { return ((lanes_ & 15) ? low_lanes : 0) | ((lanes_ >> 4) ? high_lanes : 0); }
  template <unsigned Halves = both_halves>
  void add_into(Real* node, Real c) const {
    for (int q = 0; q < pack_width; ++q)
      if ((lanes_ >> q) & 1) node[q] = std::fma(c, source_[q], node[q]);
  }

 private:
  Pack source_;
  unsigned lanes_;
};
#endif
}  // namespace num

}  // namespace latmpm::mpm
