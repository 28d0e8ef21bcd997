// One grid node's eight lanes as a single SIMD value (GCC/Clang vector extension): the P2G
// and G2P inner loops become a handful of full-width multiply-adds per node — one AVX-512
// instruction each, or two AVX2 ones — instead of scalar arithmetic per lane.
#pragma once

#include "mpm/real.hpp"
#include "mpm/simd.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

using NodeLanes = Pack;  // lane::count == pack_width
static_assert(lane::count == pack_width);

inline NodeLanes load_lanes(const Real* node) { return num::load<NodeLanes>(node); }

inline void store_lanes(Real* node, const NodeLanes& v) { num::store(node, v); }

inline NodeLanes splat(Real x) { return NodeLanes{} + x; }

// s·v and acc + s·v over a node's eight lanes, for the P2G and G2P node loops. Where the CPU
// has no eight-lane vectors of Real (num::pack_in_halves: a NodeLanes is two four-lane
// halves), GCC 12 builds the eight-lane copy of s that `s * v` implies through the stack —
// eight scalar stores read back as 16-byte pieces, a store-forwarding stall each — and the
// node loops of P2G and G2P ran 3–4× slower than their arithmetic (2026-11-28, AMD Zen 3:
// docs/benchmarks.md, "Eight-lane splats on AVX2"). There each native half is multiplied by a
// four-lane copy of s. Elsewhere these are the plain expressions, written in the order of the
// expressions they replace (acc + s·v + t·u = plus_scaled(plus_scaled(acc, s, v), t, u)), so
// the compiler contracts them as before: on AVX2 the results are the same bits (42 digests);
// on AVX-512 the kernels have the same count of each floating-point instruction (not run).
inline NodeLanes scaled(Real s, const NodeLanes& v) {
  if constexpr (num::pack_in_halves) {
    const Axes copies = {s, s, s, s};
    return num::join_halves(copies * num::low_half(v), copies * num::high_half(v));
  }
  return s * v;
}
inline NodeLanes plus_scaled(const NodeLanes& acc, Real s, const NodeLanes& v) {
  if constexpr (num::pack_in_halves) {
    const Axes copies = {s, s, s, s};
    return num::join_halves(num::low_half(acc) + copies * num::low_half(v),
                            num::high_half(acc) + copies * num::high_half(v));
  }
  return acc + s * v;
}

}  // namespace latmpm::mpm
