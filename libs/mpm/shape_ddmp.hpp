// DDMP, the dual domain material point method (Zhang, Ma & Giguere 2011; Paper A Sec. 2,
// Eq. 4–8): the original MPM's linear shape functions S_i for mass, momentum and velocity,
// and a modified gradient for the internal force and the velocity gradient,
//   ∇̄S_i(x) = α(x) ∇S_i(x) + [1 − α(x)] Σ_j S_j(x)/V_j ∫_Ω S_j ∇S_i dV,            (Eq. 7)
// j over the 8 corners of the particle's cell, so i reaches one node further per side:
// a 4×4×4 stencil, nodes c−1 … c+2 for a particle in cell c.
//
// The smoothing integral is geometry only (Paper A: "independent of the stresses and
// locations of material points, and only needs to be calculated once"): Ω is the whole
// grid, V_j = ∫ S_j dV = h³ at every node of the (unbounded) sparse grid, and for linear
// hat functions ∫ S_j ∂_x S_i dV = h² D(i_x − j_x) M(i_y − j_y) M(i_z − j_z), the same
// separable 27-node stencil for every node: D(±1) = ±½, D(0) = 0 (the derivative
// direction), M(0) = ⅔, M(±1) = ⅙ (the others). Since Σ_i S_i = 1 and Σ_i x_i S_i = x on
// the whole grid, Σ_i ∫ S_j ∇S_i = 0 and Σ_i x_i ⊗ ∫ S_j ∇S_i = V_j I, so Eq. 8 holds at
// every point, free surfaces or not. Nodes outside the material then carry smoothed force
// with no mass of their own: ddmp_grid.hpp hands them, and every node of small mass, to
// their neighbours (the DDMP group's distribution coefficients).
//
// α is Eq. 5 as printed, in 3D (n_c = 8, d = 3): α = ½ {Π_{j=1..8} 2 S_j}^{1/14}. With
// Π_j 2 S_j = 2⁸ Π_a (f_a (1 − f_a))⁴ = 2^(−16) Π_a (4 f_a (1 − f_a))⁴ it is
// peak · Π_a [4 f_a (1 − f_a)]^exponent with peak ½·2^(−16/14) = 0.2264 and exponent 2/7,
// f the position in the cell: continuous across cells (0 on every face). Peak and exponent
// stay settings for studies (Settings::ddmp_alpha_peak, ddmp_alpha_exponent).
//
// Two evaluations of the same sums: DdmpShape, per particle over the 4×4×4 nodes (the
// reference the tests hold the other to), and DdmpGridShape (the default,
// Settings::ddmp_on_grid): Paper A's Eq. 4 on the grid (ddmp_grid.hpp), with only the
// cell's 8 nodes per particle.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "mpm/stencil.hpp"

namespace latmpm::mpm {

struct DdmpShape : ShapeFlags {
  static constexpr int nodes_per_axis = 4;
  static constexpr int reach_below = -1;
  static constexpr int reach_above = 2;
  static constexpr bool uses_half_size = false;
  static constexpr bool stretches_with_f = false;
  static constexpr bool smoothed_gradient = true;
  static constexpr bool per_node_gradient = true;
};

// DDMP with the smoothed part on the grid (Paper A Eq. 4; ddmp_grid.hpp): the particle
// touches only its cell's 8 nodes, with S, α∇S and the 8 weights (1 − α) S_j of the nodal
// stress and velocity gradient; grid passes do the rest (their force reaches one node
// further per side: the solver activates those blocks too).
struct DdmpGridShape : ShapeFlags {
  static constexpr int nodes_per_axis = 2;
  static constexpr int reach_below = 0;
  static constexpr int reach_above = 1;
  static constexpr bool uses_half_size = false;
  static constexpr bool stretches_with_f = false;
  static constexpr bool smoothed_gradient = true;
  static constexpr bool smoothed_on_grid = true;
};

// The 1D factors of the smoothing integral over h^(dimension): ∫ S_j S_i dx = h M(i − j),
// ∫ S_j S_i' dx = D(i − j), offsets i − j ∈ {−1, 0, 1}.
inline constexpr Real ddmp_smoothing_mass(int offset) {
  return offset == 0 ? Real(2) / 3 : (offset == 1 || offset == -1 ? Real(1) / 6 : Real(0));
}
inline constexpr Real ddmp_smoothing_slope(int offset) {
  return offset == 1 ? Real(0.5) : (offset == -1 ? Real(-0.5) : Real(0));
}

struct DdmpStencil : Stencil<4> {
  Real alpha;          // α(x), Eq. 5
  Vec3 smoothed[64];   // (1 − α) Σ_j S_j/V_j ∫ S_j ∇S_i dV for node (i, j, k) at [(i·4 + j)·4 + k], 1/m
};

// The partition function α(x) = peak · Π_axes [4 f_a (1 − f_a)]^exponent; the default is
// Eq. 5 as printed in 3D (header comment).
struct DdmpPartition {
  Real peak = Real(0.5) * std::pow(Real(2), Real(-16) / 14);  // α at the cell centre, in (0, 1]
  Real exponent = Real(2) / 7;                                  // per axis
};

// α(x) from the particle's fractional position f ∈ [0, 1)³ in its cell.
inline Real ddmp_partition(const Vec3& f, const DdmpPartition& alpha = {}) {
  Real p = 1;
  for (int a = 0; a < 3; ++a) p *= 4 * f[a] * (1 - f[a]);
  if (!(p > 0)) return 0;
  return alpha.peak * std::pow(p, alpha.exponent);
}

// α per point for one step (DdmpGridShape): every pass of a step sees the point at x^n, so
// α is computed once per point at the step's start (ddmp_partition_of_points) and the
// passes read it at values[p]. values == nullptr: compute every time.
struct DdmpAlphaCache {
  Real* values = nullptr;
};

// The position f ∈ [0, 1)³ of x in its cell, and the cell.
inline Vec3 ddmp_cell_position(const Vec3& x, Real inv_h, int cell[3]) {
  Vec3 f;
  for (int a = 0; a < 3; ++a) {
    const Real xi = x[a] * inv_h;
    cell[a] = floor_to_int(xi);
    f[a] = xi - Real(cell[a]);
  }
  return f;
}

// α of the points x[0 … n) into alpha: ddmp_partition with peak · exp(exponent · ln p) in
// place of pow, with Eigen's vectorised array log and exp (one scalar pow per point and step
// was 8 % of a DDMP step), in rounds of points whose values stay in L1. Agrees with
// ddmp_partition to a few ulps (test_ddmp, "α of many points at once"). The factors
// 4 f (1 − f) are taken over the round's 3 · count coordinates as one array, which vectorises
// (one point at a time, the floor, its conversion and the products were half of this pass:
// 7.8 → 6.5 % of a paper-cell T2P30 DDMP step, perf 2026-11-29; what is left waits on the
// positions' loads). The same operations in the same order as ddmp_partition, so the
// same bits: f = x·h⁻¹ − ⌊x·h⁻¹⌋, g = 4 f (1 − f), p = (g_x g_y) g_z.
inline void ddmp_partition_of_points(const Vec3* x, size_t n, Real inv_h, const DdmpPartition& partition, Real* alpha) {
  static_assert(sizeof(Vec3) == 3 * sizeof(Real), "a vector of Vec3 is its coordinates one after the other");
  using Array = Eigen::Array<Real, Eigen::Dynamic, 1>;
  constexpr size_t piece = 512;  // points a round: their factors and α stay in L1
  alignas(64) Real factor[3 * piece];
  alignas(64) Real smooth_part[piece];
  for (size_t first = 0; first < n; first += piece) {
    const size_t count = std::min(piece, n - first);
    const Eigen::Map<const Array> coordinates(x[first].data(), Eigen::Index(3 * count));
    Eigen::Map<Array> g(factor, Eigen::Index(3 * count));
    g = coordinates * inv_h;
    g = g - g.floor();
    g = 4 * g * (1 - g);
    Eigen::Map<Array> out(alpha + first, Eigen::Index(count));
    for (size_t p = 0; p < count; ++p) out[Eigen::Index(p)] = factor[3 * p] * factor[3 * p + 1] * factor[3 * p + 2];
    // The log and exp as an array expression of its own, which Eigen vectorises (inside
    // select() it evaluated them coefficient by coefficient through libm: 4 % of a DDMP step).
    Eigen::Map<Array> smooth(smooth_part, Eigen::Index(count));
    smooth = partition.peak * (partition.exponent * out.log()).exp();
    out = (out > 0).select(smooth, Real(0));
  }
}

// The particle's cell, its linear weights and α: what both evaluations of Eq. 7 share.
struct DdmpCellFrame {
  int cell[3];
  Real N[3][2];  // linear weights of the cell's two nodes per axis
  Real alpha;
};

inline DdmpCellFrame ddmp_cell_frame(const Vec3& x, Real inv_h, const DdmpPartition& partition,
                                     DdmpAlphaCache cache = {}, size_t p = 0) {
  DdmpCellFrame fr;
  const Vec3 f = ddmp_cell_position(x, inv_h, fr.cell);
  for (int a = 0; a < 3; ++a) {
    fr.N[a][0] = 1 - f[a];
    fr.N[a][1] = f[a];
  }
  fr.alpha = cache.values ? cache.values[p] : ddmp_partition(f, partition);
  return fr;
}

// The stencil at x (m) for cell size 1/inv_h. Without `smoothed` only S and α∇S are filled
// (passes that need no gradient).
inline DdmpStencil make_ddmp_stencil(const Vec3& x, Real inv_h, const DdmpPartition& partition = {},
                                     bool smoothed = true) {
  DdmpStencil st;
  const DdmpCellFrame fr = ddmp_cell_frame(x, inv_h, partition);
  const auto& N = fr.N;
  for (int a = 0; a < 3; ++a) st.base[a] = fr.cell[a] - 1;
  st.alpha = fr.alpha;
  for (int k = 0; k < 4; ++k) {
    st.w[k] = Axes{};
    st.dw[k] = Axes{};
  }
  for (int a = 0; a < 3; ++a) {
    st.w[1][a] = N[a][0];
    st.w[2][a] = N[a][1];
    st.dw[1][a] = -fr.alpha * inv_h;  // α ∇S: the derivative factor carries α (the others are S)
    st.dw[2][a] = fr.alpha * inv_h;
  }
  if (!smoothed) {
    for (auto& g : st.smoothed) g.setZero();
    return st;
  }
  // Σ_j S_j(x)/h³ ∫ S_j ∇S_i dV is a tensor product of 1D sums over the cell's two nodes j
  // per axis: s = Σ_j N_j M(i − j), sd = Σ_j N_j D(i − j)/h; stencil node k is i = c − 1 + k.
  Real s[3][4], sd[3][4];
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < 4; ++k) {
      s[a][k] = sd[a][k] = 0;
      for (int j = 0; j < 2; ++j) {
        const int offset = k - (j + 1);
        s[a][k] += N[a][j] * ddmp_smoothing_mass(offset);
        sd[a][k] += N[a][j] * ddmp_smoothing_slope(offset) * inv_h;
      }
    }
  const Real beta = 1 - fr.alpha;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        st.smoothed[(i * 4 + j) * 4 + k] =
            beta * Vec3(sd[0][i] * s[1][j] * s[2][k], s[0][i] * sd[1][j] * s[2][k], s[0][i] * s[1][j] * sd[2][k]);
  return st;
}

// DdmpGridShape's stencil: S and α∇S on the particle's cell's 8 nodes (base = the cell), and
// the weights (1 − α) S_j of the nodal σ^d_j and L_j at its corners j (index 4 j_x + 2 j_y + j_z),
// so that Σ_j corner[j] L_j is Eq. 7's smoothed part of L̄ (ddmp_grid.hpp).
struct DdmpCornerStencil : Stencil<2> {
  Real alpha;
  Real corner[8];
};

inline DdmpCornerStencil make_ddmp_corner_stencil(const Vec3& x, Real inv_h, const DdmpPartition& partition = {},
                                                   DdmpAlphaCache cache = {}, size_t p = 0) {
  DdmpCornerStencil st;
  const DdmpCellFrame fr = ddmp_cell_frame(x, inv_h, partition, cache, p);
  st.alpha = fr.alpha;
  for (int a = 0; a < 3; ++a) {
    st.base[a] = fr.cell[a];
    st.w[0][a] = fr.N[a][0];
    st.w[1][a] = fr.N[a][1];
    st.dw[0][a] = -fr.alpha * inv_h;
    st.dw[1][a] = fr.alpha * inv_h;
  }
  st.w[0][3] = st.w[1][3] = st.dw[0][3] = st.dw[1][3] = 0;
  const Real beta = 1 - fr.alpha;
  for (int j = 0; j < 8; ++j) st.corner[j] = beta * fr.N[0][j >> 2] * fr.N[1][(j >> 1) & 1] * fr.N[2][j & 1];
  return st;
}

}  // namespace latmpm::mpm
