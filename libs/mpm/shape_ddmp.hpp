// DDMP, the dual domain material point method (Zhang, Ma & Giguere 2011; Paper A Sec. 2,
// Eq. 4–8): the original MPM's linear shape functions S_i for mass, momentum and velocity,
// and a modified gradient for the internal force and the velocity gradient,
//   ∇̄S_i(x) = α(x) ∇S_i(x) + [1 − α(x)] Σ_j S_j(x)/V_j ∫_Ω S_j ∇S_i dV,            (Eq. 7)
// j over the 8 corners of the particle's cell, so i reaches one node further per side:
// a 4×4×4 stencil, nodes c−1 … c+2 for a particle in cell c.
//
// Decision (docs/solver.md, "DDMP", "Decision — α"): the partition function is
//   α(x) = peak · Π_axes [4 f_a (1 − f_a)]^exponent,  f the position in the cell,
// default peak 1, exponent 1/8 (Settings::ddmp_alpha_peak, ddmp_alpha_exponent). Eq. 5 read
// literally in 3D, α = ½ {Π_{j=1..8} 2 S_j}^{1/14}, is this form with peak ½·2^(−16/14) =
// 0.227 and exponent 2/7. The smoothed part is a two-cell-wide nodal average, blind to
// odd–even nodal velocity patterns; only α ∇S resists them. With Eq. 5's α a 4³-cell block
// has ~120 such near-zero-energy modes below its lowest physical one, the bending mode
// loses its energy into them once material crosses cells (measured: tests/mpm). The paper
// asks of α only that it be continuous, positive and zero on cell faces; this one is.
//
// Decision (docs/solver.md, "DDMP"): Ω is the union of the grid cells at least half filled
// with deformable material this step (Σ V0 of their points ≥ h³/2, cell_occupancy.hpp), and
// V_j = ∫_Ω S_j dV = (Ω cells around node j) · h³/8. The cell integrals ∫_e S_j ∇S_i dV
// are geometry only: on a regular grid one 8×8 table for every cell (computed once, below).
// With V_j consistent with Ω, Σ_i ∫_Ω S_j ∇S_i = ∫_Ω S_j ∇1 = 0 and
// Σ_i x_i ⊗ ∫_Ω S_j ∇S_i = ∫_Ω S_j I = V_j I. Corners j with V_j = 0 (no Ω cell around
// them) drop out and the others' S_j are renormalised to sum to one, so Eq. 8 —
// Σ_i ∇̄S_i = 0 and Σ_i x_i ⊗ ∇̄S_i = I — holds exactly at every point; a point with no Ω
// cell around any corner takes the plain gradient (α = 1). Every node the smoothed part
// touches is a corner of a well-filled cell and so has a sizeable mass. (Ω = the whole grid
// pushes force onto empty nodes and reads their zero velocity back into L; Ω = every cell
// holding a point gives a cell that one point has just entered a full share of the
// neighbours' smoothed force on corners that point alone weighs, with a tiny mass: the
// buckling column at two cells across inverted at step 1613, measured.)
//
// The stencil is the tensor-product Stencil<4> of the other shape functions — weights
// S (zero on the outer nodes) and derivatives α ∇S — plus the non-separable smoothed part
// (1 − α) Σ_j ..., one vector per stencil node; transfer.hpp adds it where the shape says
// `smoothed_gradient`. That per-particle form is the reference; runs by default use
// DdmpGridShape (below, Settings::ddmp_on_grid): the same sums regrouped as Paper A's Eq. 4
// on the grid (ddmp_grid.hpp), with only the cell's 8 nodes per particle.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>

#include "mpm/stencil.hpp"

namespace latmpm::mpm {

struct DdmpShape {
  static constexpr int nodes_per_axis = 4;
  static constexpr int reach_below = -1;
  static constexpr int reach_above = 2;
  static constexpr bool uses_half_size = false;
  static constexpr bool stretches_with_f = false;
  static constexpr bool smoothed_gradient = true;
};

// DDMP with the smoothed part on the grid (Paper A Eq. 4; ddmp_grid.hpp): the particle
// touches only its cell's 8 nodes, with S, α∇S and the 8 weights (1 − α) S_j of the nodal
// stress and velocity gradient; grid passes over the cells of Ω do the rest. The stencil
// reaches the cell's nodes; the cells around it (Ω's mask) are read one further below.
struct DdmpGridShape {
  static constexpr int nodes_per_axis = 2;
  static constexpr int reach_below = 0;
  static constexpr int reach_above = 1;
  static constexpr bool uses_half_size = false;
  static constexpr bool stretches_with_f = false;
  static constexpr bool smoothed_gradient = true;
  static constexpr bool smoothed_on_grid = true;
};

// Shapes without a smoothed gradient part (all others).
template <class Shape, class = void>
struct has_smoothed_gradient : std::false_type {};
template <class Shape>
struct has_smoothed_gradient<Shape, std::void_t<decltype(Shape::smoothed_gradient)>>
    : std::bool_constant<Shape::smoothed_gradient> {};

// DDMP shapes whose smoothed part is evaluated on the grid (DdmpGridShape).
template <class Shape, class = void>
struct has_grid_smoothed_gradient : std::false_type {};
template <class Shape>
struct has_grid_smoothed_gradient<Shape, std::void_t<decltype(Shape::smoothed_on_grid)>>
    : std::bool_constant<Shape::smoothed_on_grid> {};

// Bit of the cell c + (dx, dy, dz), d ∈ {−1, 0, 1}, in a 27-bit occupancy mask around c.
constexpr int ddmp_cell_bit(int dx, int dy, int dz) { return (dx + 1) * 9 + (dy + 1) * 3 + (dz + 1); }
inline constexpr uint32_t ddmp_all_occupied = (uint32_t(1) << 27) - 1;

struct DdmpStencil : Stencil<4> {
  Real alpha;          // α(x), the partition function (Eq. 5's role)
  Vec3 smoothed[64];   // (1 − α) Σ_j S_j/V_j ∫_Ω S_j ∇S_i dV for node (i, j, k) at [(i·4 + j)·4 + k], 1/m
};

// The partition function α(x) = peak · Π_axes [4 f_a (1 − f_a)]^exponent (Eq. 5's role).
struct DdmpPartition {
  Real peak = 1;                // α at the cell centre, in (0, 1]
  Real exponent = Real(1) / 8;  // per axis; α ~ (4 d/h)^exponent at a distance d from a face
};
// Eq. 5 as printed, in 3D (n_c = 8, d = 3): ½ {Π_j 2 S_j}^{1/14} with Π_j 2 S_j =
// 2⁸ Π_a (f_a (1 − f_a))⁴ = 2^(−16) Π_a (4 f_a (1 − f_a))⁴, i.e. peak ½·2^(−16/14), exponent 2/7.
inline const DdmpPartition ddmp_eq5_partition{Real(0.5) * std::pow(Real(2), Real(-16) / 14), Real(2) / 7};

// α(x) from the particle's fractional position f ∈ [0, 1)³ in its cell.
inline Real ddmp_partition(const Vec3& f, const DdmpPartition& alpha = {}) {
  Real p = 1;
  for (int a = 0; a < 3; ++a) p *= 4 * f[a] * (1 - f[a]);
  if (!(p > 0)) return 0;
  // p^(1/2^k) as k square roots for the usual exponents (the default 1/8): a pow per particle
  // and pass was a sixth of DDMP's step.
  Real e = alpha.exponent;
  int roots = 0;
  while (roots < 4 && e != 1 && e * 2 <= 1) e *= 2, ++roots;
  if (e == 1) {
    for (int k = 0; k < roots; ++k) p = std::sqrt(p);
    return alpha.peak * p;
  }
  return alpha.peak * std::pow(p, alpha.exponent);
}

// The particle's cell and what both ways of evaluating Eq. 7 share: the linear weights, the
// corners with an Ω cell around them (count: how many) and the share of S they hold, α.
struct DdmpCellFrame {
  int cell[3];
  Vec3 f;                // position in the cell, [0, 1)³
  Real N[3][2];          // linear weights of the cell's two nodes per axis
  int count[2][2][2];    // Ω cells around each corner: V_j = count h³/8
  Real covered;          // Σ S_j over the corners with count > 0
  Real alpha;            // α(x); 1 when no corner has an Ω cell around it
};

// `occupied`: the 27-bit mask of the cells of Ω around x's cell (ddmp_cell_bit).
inline DdmpCellFrame ddmp_cell_frame(const Vec3& x, Real inv_h, uint32_t occupied, const DdmpPartition& partition) {
  DdmpCellFrame fr;
  for (int a = 0; a < 3; ++a) {
    const Real xi = x[a] * inv_h;
    fr.cell[a] = floor_to_int(xi);
    fr.f[a] = xi - Real(fr.cell[a]);
    fr.N[a][0] = 1 - fr.f[a];
    fr.N[a][1] = fr.f[a];
  }
  // The 8 cells around corner j, as a mask of the 27 (computed once).
  static const auto around = [] {
    std::array<uint32_t, 8> m{};
    for (int j = 0; j < 8; ++j)
      for (int e = 0; e < 8; ++e)
        m[size_t(j)] |= uint32_t(1) << ddmp_cell_bit((j >> 2) - 1 + (e >> 2), ((j >> 1) & 1) - 1 + ((e >> 1) & 1),
                                                     (j & 1) - 1 + (e & 1));
    return m;
  }();
  fr.covered = 0;
  for (int jx = 0; jx < 2; ++jx)
    for (int jy = 0; jy < 2; ++jy)
      for (int jz = 0; jz < 2; ++jz) {
        const int n = __builtin_popcount(occupied & around[size_t(4 * jx + 2 * jy + jz)]);
        fr.count[jx][jy][jz] = n;
        if (n > 0) fr.covered += fr.N[0][jx] * fr.N[1][jy] * fr.N[2][jz];
      }
  fr.alpha = fr.covered > 0 ? ddmp_partition(fr.f, partition) : Real(1);
  return fr;
}

// One cell e, its corners l, b ∈ {0, 1}³ (index 4 l_x + 2 l_y + l_z):
// ∫_e S_l ∇S_b dV = h² (d(l_x, b_x) m(l_y, b_y) m(l_z, b_z), m d m, m m d) with
// d(l, b) = ±1/2 (+ for b = 1) and m(l, b) = 1/3 (l = b) or 1/6: one table for every cell,
// entry [l][b] = the integral over h².
inline const std::array<std::array<Vec3, 8>, 8>& ddmp_cell_integrals() {
  static const auto table = [] {
    std::array<std::array<Vec3, 8>, 8> t;
    auto m = [](int l, int b) { return l == b ? Real(1) / 3 : Real(1) / 6; };
    auto d = [](int, int b) { return b == 1 ? Real(0.5) : Real(-0.5); };
    for (int l = 0; l < 8; ++l)
      for (int b = 0; b < 8; ++b) {
        const int lx = l >> 2, ly = (l >> 1) & 1, lz = l & 1, bx = b >> 2, by = (b >> 1) & 1, bz = b & 1;
        t[size_t(l)][size_t(b)] = Vec3(d(lx, bx) * m(ly, by) * m(lz, bz), m(lx, bx) * d(ly, by) * m(lz, bz),
                                       m(lx, bx) * m(ly, by) * d(lz, bz));
      }
    return t;
  }();
  return table;
}

// The stencil at x (m) for cell size 1/inv_h, with `occupied` the 27-bit mask of the cells
// of Ω around x's cell (ddmp_cell_bit).
// Without `smoothed` only S and α∇S are filled (passes that need no gradient: the smoothed
// part is most of the cost).
inline DdmpStencil make_ddmp_stencil(const Vec3& x, Real inv_h, uint32_t occupied, const DdmpPartition& partition = {},
                                     bool smoothed = true) {
  DdmpStencil st;
  const DdmpCellFrame fr = ddmp_cell_frame(x, inv_h, occupied, partition);
  const auto& N = fr.N;
  const auto& count = fr.count;
  const Real covered = fr.covered;
  for (int a = 0; a < 3; ++a) st.base[a] = fr.cell[a] - 1;
  auto is_occupied = [&](int dx, int dy, int dz) { return (occupied >> ddmp_cell_bit(dx, dy, dz)) & 1u; };
  const Real alpha = fr.alpha;
  st.alpha = alpha;
  for (int k = 0; k < 4; ++k) {
    st.w[k] = Axes{};
    st.dw[k] = Axes{};
  }
  for (int a = 0; a < 3; ++a) {
    st.w[1][a] = N[a][0];
    st.w[2][a] = N[a][1];
    st.dw[1][a] = -alpha * inv_h;  // α ∇S: the derivative factor carries α (the others are S)
    st.dw[2][a] = alpha * inv_h;
  }
  const Real beta = 1 - alpha;
  if (!smoothed) {
    for (auto& g : st.smoothed) g.setZero();
    return st;
  }
  if (occupied == ddmp_all_occupied) {
    // Interior: every node's V_j = h³ and the sum over cells is the whole-grid integral, a
    // tensor product: ∫ N_j N_i dx = h (2/3, 1/6), ∫ N_j N_i' dx = ±1/2 for i = j ± 1.
    Real s[3][4], sd[3][4];
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < 4; ++k) {
        s[a][k] = sd[a][k] = 0;
        for (int j = 0; j < 2; ++j) {
          const int offset = k - (j + 1);  // i − j in nodes
          const Real mass = offset == 0 ? Real(2) / 3 : (offset == 1 || offset == -1 ? Real(1) / 6 : 0);
          const Real slope = offset == 1 ? Real(0.5) : (offset == -1 ? Real(-0.5) : 0);
          s[a][k] += N[a][j] * mass;
          sd[a][k] += N[a][j] * slope * inv_h;
        }
      }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k)
          st.smoothed[(i * 4 + j) * 4 + k] = beta * Vec3(sd[0][i] * s[1][j] * s[2][k], s[0][i] * sd[1][j] * s[2][k],
                                                          s[0][i] * s[1][j] * sd[2][k]);
    return st;
  }
  for (auto& g : st.smoothed) g.setZero();
  if (!(covered > 0)) return st;
  const auto& table = ddmp_cell_integrals();
  for (int jx = 0; jx < 2; ++jx)
    for (int jy = 0; jy < 2; ++jy)
      for (int jz = 0; jz < 2; ++jz) {
        // S_j renormalised over the corners in Ω's reach; V_j = count h³/8 (cells e around j:
        // offsets d = j − 1 + e); the cell integrals are h² × table: S_j/V_j ∫ = S_j 8/(count h) × table.
        const Real S = N[0][jx] * N[1][jy] * N[2][jz] / covered;
        const int n = count[jx][jy][jz];
        if (!(S > 0) || n == 0) continue;
        const Real scale = beta * S * 8 / Real(n) * inv_h;
        for (int ex = 0; ex < 2; ++ex)
          for (int ey = 0; ey < 2; ++ey)
            for (int ez = 0; ez < 2; ++ez) {
              const int dx = jx - 1 + ex, dy = jy - 1 + ey, dz = jz - 1 + ez;
              if (!is_occupied(dx, dy, dz)) continue;
              // j is corner l = 1 − e of cell d; the cell's corner b is stencil node d + b + 1.
              const auto& row = table[size_t(4 * (1 - ex) + 2 * (1 - ey) + (1 - ez))];
              Vec3* first = st.smoothed + ((dx + 1) * 4 + (dy + 1)) * 4 + (dz + 1);
              for (int b = 0; b < 8; ++b) first[((b >> 2) * 4 + ((b >> 1) & 1)) * 4 + (b & 1)] += scale * row[size_t(b)];
            }
      }
  return st;
}

// DdmpGridShape's stencil: S and α∇S on the particle's cell's 8 nodes (base = the cell), and
// the weights (1 − α) S̃_j of the nodal σ^d_j and L_j at its corners j (index 4 j_x + 2 j_y + j_z),
// S̃_j = S_j renormalised over the corners with an Ω cell around them, 0 for the others —
// so that Σ_j corner[j] L_j is Eq. 7's smoothed part of L̄ exactly (ddmp_grid.hpp).
struct DdmpCornerStencil : Stencil<2> {
  Real alpha;
  Real corner[8];
};

inline DdmpCornerStencil make_ddmp_corner_stencil(const Vec3& x, Real inv_h, uint32_t occupied,
                                                  const DdmpPartition& partition = {}) {
  DdmpCornerStencil st;
  const DdmpCellFrame fr = ddmp_cell_frame(x, inv_h, occupied, partition);
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
  for (int j = 0; j < 8; ++j) {
    const int jx = j >> 2, jy = (j >> 1) & 1, jz = j & 1;
    st.corner[j] = fr.count[jx][jy][jz] > 0 && fr.covered > 0
                       ? beta * (fr.N[0][jx] * fr.N[1][jy] * fr.N[2][jz] / fr.covered)
                       : Real(0);
  }
  return st;
}

}  // namespace latmpm::mpm
