// One grid node's eight lanes as a single SIMD value (GCC/Clang vector extension): the P2G
// and G2P inner loops become a handful of full-width multiply-adds per node — one AVX-512
// instruction each, or two AVX2 ones — instead of scalar arithmetic per lane.
#pragma once
#include <cstring>

#include "mpm/real.hpp"
#include "mpm/simd.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

using NodeLanes = Pack;  // lane::count == pack_width
static_assert(lane::count == pack_width);

inline NodeLanes load_lanes(const Real* node) {
  NodeLanes v;
  std::memcpy(&v, node, sizeof v);
  return v;
}

inline void store_lanes(Real* node, const NodeLanes& v) { std::memcpy(node, &v, sizeof v); }

inline NodeLanes splat(Real x) { return NodeLanes{} + x; }

}  // namespace latmpm::mpm
