// Particle–grid transfers for one bucket, compiled once per shape function and mode:
//   scatter_bucket: particles to grid (P2G) — mass, momentum, internal force, constraints
//   gather_bucket:  grid to particles (G2P) — velocity (PIC/FLIP), position, F and stress
// Both build the same tensor-product stencil (stencil.hpp) from the particle's position at
// the start of the step and work on the bucket's dense buffer (bucket_buffer.hpp).
// Equations (docs/solver.md): m_i = Σ S_ip m_p, p_i = Σ S_ip m_p v_p,
// f_i = −Σ V_p σ_p ∇S_ip (Paper B Eq. 2–4); v_p ← α(v_p + Σ S_ip Δv_i) + (1−α) Σ S_ip v_i,
// x_p ← x_p + dt Σ S_ip v_i, L_p = Σ v_i ⊗ ∇S_ip, F_p ← (I + dt L_p) F_p.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "mpm/body.hpp"
#include "mpm/bucket_buffer.hpp"
#include "mpm/ddmp_grid.hpp"
#include "mpm/ddmp_stabilization.hpp"
#include "mpm/material_history.hpp"
#include "mpm/material_model.hpp"
#include "mpm/node_lanes.hpp"
#include "mpm/particles.hpp"
#include "mpm/shape_ddmp_subpoints.hpp"
#include "mpm/shape_functions.hpp"

namespace latmpm::mpm {

// What the transfers need to know of a body.
struct BodyInfo {
  BodyRole role = BodyRole::deformable;
  Vec3 velocity = Vec3::Zero();  // prescribed velocity of a driven body, m/s
  MaterialModel model;
  // Deformable body: its model's history variables' columns in Particles::history, in the
  // model's order (material_history.hpp); empty for a model without history.
  std::vector<uint32_t> history_columns;
  // Deformable body with held points: unit vector from the body's centroid toward its held
  // points' centroid (the held face's outward normal), zero when that is undefined.
  Vec3 hold_outward = Vec3::Zero();
  bool hold_slip = false;  // held nodes keep their velocity along the face (BodySettings::hold_slip)
  // A fixed body whose nodes are marked from a list made once (fixed_body_nodes.hpp): the
  // transfers leave its points out.
  bool marked_once = false;
  // Deformable body under stabilized DDMP: β times its moduli (ddmp_stabilization.hpp);
  // μ = 0: none.
  LinearElastic ddmp_stabilization{};
};

// Which node lanes a particles-to-grid pass fills.
template <bool Mass, int MomentumLane, bool Force, bool Constraint>
struct ScatterMode {
  static constexpr bool mass = Mass;
  static constexpr int momentum_lane = MomentumLane;  // receives m_p v_p; −1: none
  static constexpr bool force = Force;
  static constexpr bool constraint = Constraint;
};

// Which particle quantities a grid-to-particles pass updates.
template <bool Velocity, bool Position, int GradientLane>
struct GatherMode {
  static constexpr bool velocity = Velocity;  // v_p from new velocity (lanes 1–3), change (4–6)
  static constexpr bool position = Position;  // x_p += dt Σ S v_i (lanes 1–3)
  static constexpr int gradient_lane = GradientLane;  // velocity lanes for L; −1: F, σ unchanged
};

enum class ParticleFault { none, not_finite, inverted, left_grid };

// Per-bucket sums of one gather pass (summed over buckets in order: deterministic).
struct BucketTally {
  Real kinetic = 0, strain = 0, gravity_power = 0;
  Real dissipation = 0;  // Σ V0 × dissipated energy density (material_history.hpp), J
  // Kinetic energy the FLIP/PIC blend removed in this pass: Σ ½ m (|v_FLIP|² − |v|²), v_FLIP
  // = v + Σ S Δv_I the pure FLIP update and v the blended one, J. A numerical dissipation.
  Real blend_dissipation = 0;
  // Kinetic energy of the points' FLIP increments in this pass: Σ ½ m |Δv_p|², Δv_p = Σ S Δv_I
  // (J). Against the grid's Σ ½ m_I |Δv_I|² it gives the projection loss (grid_update.hpp).
  Real increment_energy = 0;
  Real max_speed_sq = 0;  // m²/s²
  Real max_wave_speed_sq = 0;  // m²/s², from the smallest J of each run (see below)
  std::array<int, 3> cell_min{}, cell_max{};
  BucketColumns cells;  // the cells' columns (within the drift limit)
  bool drifted = false;
  ParticleFault fault = ParticleFault::none;
  uint32_t fault_particle = 0;
};

struct RunTally {
  Vec3 mass_position = Vec3::Zero();  // Σ m x, kg m
  Real mass = 0;
};

// Grid coordinate range particles must stay inside (cells): the bucket keys' range.
inline constexpr int max_cell_coord = (1 << 16) - 64;

// The particle-domain half-sizes a shape function uses (m); cpGIMP stretches them with the
// diagonal of F (Sadeghirad et al. 2011), clamped so the stencil stays N nodes wide.
template <class Shape>
inline Vec3 stencil_half_size(const Particles& ps, size_t p, Real h) {
  if constexpr (!Shape::uses_half_size) {
    return Vec3::Zero();
  } else {
    Vec3 l = ps.half_size0[p].template cast<Real>();
    if constexpr (Shape::stretches_with_f) l = l.cwiseProduct(ps.deformation[p].diagonal().cwiseAbs().template cast<Real>());
    for (int a = 0; a < 3; ++a) l[a] = std::clamp(l[a], Real(1e-3) * h, Shape::max_half * h);
    return l;
  }
}

// The stencil of particle p: the shape's tensor-product stencil, or DDMP's with the run's
// partition function α (from the bucket buffer).
// Gradient = false: the pass needs weights only (DDMP then skips its smoothed part).
template <class Shape, bool Gradient = true>
inline auto particle_stencil(const Particles& ps, size_t p, Real h, const BucketBuffer& buffer) {
  if constexpr (Shape::uses_domain_vertices)
    return make_cpdi_box_stencil(ps, p, h);
  else if constexpr (Shape::smoothed_on_grid && Shape::per_node_gradient)
    return make_ddmp_subpoint_stencil(ps.position[p], ps.deformation[p].template cast<Real>(),
                                      stencil_half_size<Shape>(ps, p, h), 1 / h, buffer.ddmp_alpha);
  else if constexpr (Shape::smoothed_on_grid)
    return make_ddmp_corner_stencil(ps.position[p], 1 / h, buffer.ddmp_alpha, buffer.ddmp_alpha_cache, p);
  else if constexpr (Shape::smoothed_gradient)
    return make_ddmp_stencil(ps.position[p], 1 / h, buffer.ddmp_alpha, Gradient);
  else if constexpr (Shape::trims_zero_planes)
    return trim_zero_planes(make_stencil<Shape>(ps.position[p], stencil_half_size<Shape>(ps, p, h), 1 / h));
  else
    return make_stencil<Shape>(ps.position[p], stencil_half_size<Shape>(ps, p, h), 1 / h);
}

// The lane vectors of particle p's scatter: node += S·a + ∂xS·fx + ∂yS·fy + ∂zS·fz, with
// a = (m, m v) and f_i = −V σ ∇S_i, V = J V0 the current volume (−V kept for DDMP's corners).
struct ScatterLanes {
  NodeLanes a, fx, fy, fz;
  Real minus_volume = 0;
};
// The force lanes of −V σ (Voigt order xx yy zz yz xz xy): fx, fy, fz are its rows.
template <class Stress>
[[gnu::always_inline]] inline void set_force_lanes(ScatterLanes& l, Real v, const Stress& s) {
  l.fx[lane::force] = v * s[0], l.fx[lane::force + 1] = v * s[5], l.fx[lane::force + 2] = v * s[4];
  l.fy[lane::force] = v * s[5], l.fy[lane::force + 1] = v * s[1], l.fy[lane::force + 2] = v * s[3];
  l.fz[lane::force] = v * s[4], l.fz[lane::force + 1] = v * s[3], l.fz[lane::force + 2] = v * s[2];
}
template <class Mode>
[[gnu::always_inline]] inline ScatterLanes scatter_lanes(const Particles& ps, size_t p) {
  ScatterLanes l{};
  const Real m = ps.mass[p];
  if constexpr (Mode::mass) l.a[lane::mass] = m;
  if constexpr (Mode::momentum_lane >= 0)
    for (int c = 0; c < 3; ++c) l.a[Mode::momentum_lane + c] = m * ps.velocity[p][c];
  if constexpr (Mode::force) {
    l.minus_volume = -Real(ps.volume0[p]) * Real(ps.deformation[p].determinant());
    set_force_lanes(l, l.minus_volume, ps.stress[p]);
  }
  return l;
}

template <class Shape, class Mode>
void scatter_bucket(const Bucket& b, const BodyRun* runs, const Particles& ps,
                    const BodyInfo* bodies, Real h, BucketBuffer& buffer) {
  buffer.wide_points.clear();
  constexpr int N = Shape::nodes_per_axis;
  constexpr int L = lane::count;
  [[maybe_unused]] const Real inv_h = 1 / h;
  for (uint32_t r = b.run_begin; r < b.run_end; ++r) {
    const BodyRun& run = runs[r - b.run_begin];
    const bool rigid = bodies[run.body].role != BodyRole::deformable;
    if (rigid && (!Mode::constraint || bodies[run.body].marked_once)) continue;
    [[maybe_unused]] const bool stabilized = bodies[run.body].ddmp_stabilization.mu > 0;  // ddmp_stabilization.hpp
    if (buffer.field >= 0 && ps.contact_field[run.begin] != buffer.field) continue;  // another field's run
    // The stencils of up to eight points first: independent computations the CPU overlaps,
    // instead of each one's latency ahead of its point's scatter.
    decltype(particle_stencil<Shape, Mode::force>(ps, run.begin, h, buffer)) stencils[pack_width];
    for (uint32_t p0 = run.begin; p0 < run.end; p0 += pack_width) {
      const uint32_t p_end = std::min<uint32_t>(p0 + pack_width, run.end);
      for (uint32_t p = p0; p < p_end; ++p) stencils[p - p0] = particle_stencil<Shape, Mode::force>(ps, p, h, buffer);
      for (uint32_t p = p0; p < p_end; ++p) {
        const auto& st = stencils[p - p0];
        Real* first = buffer.data.data() + buffer.offset(st.base[0], st.base[1], st.base[2]);
        if constexpr (Shape::uses_domain_vertices) {  // deformable points only (cpdi_particles.hpp)
          if (st.wide) {  // past the buffer: scattered onto the grid after the buckets (step_stages.hpp)
            buffer.wide_points.push_back(p);
            continue;
          }
          const ScatterLanes l = scatter_lanes<Mode>(ps, p);
          scatter_cpdi<Mode::force, BucketBuffer::stride_i, BucketBuffer::stride_j>(st, first, l.a, l.fx, l.fy, l.fz);
        } else {
        // Rigid points mark every node they touch with their body: those nodes take the body's
        // prescribed velocity (zero unless driven). Held points of a deformable body mark the
        // touched nodes except those lying inward (against hold_outward) by more than half
        // the point's half-size: the nodes on and beyond the body's held face. Holding every
        // node they touch would freeze the whole cell band they sit in, held points included,
        // and a record layer among them would read zero stress; holding only the nodes near
        // them would leave the tiny-mass node just outside free, whose huge velocity cancels
        // the held points' strain (docs/solver.md, "Held points").
        const bool held = !rigid && (ps.flags[p] & Particles::held_flag);
        if (Mode::constraint && (rigid || held)) {
          const Real marker = Real(run.body + 1);
          const Vec3& n = bodies[run.body].hold_outward;
          const Real inward_limit = -Real(0.5) * n.cwiseAbs().dot(ps.half_size0[p].template cast<Real>());
          Real along[3][N];  // (x_node − x_p)·n, per axis part
          for (int a = 0; a < 3; ++a)
            for (int i = 0; i < N; ++i) along[a][i] = held ? ((st.base[a] + i) * h - ps.position[p][a]) * n[a] : Real(0);
          for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j)
              for (int k = 0; k < N; ++k)
                if (st.w[i][0] * st.w[j][1] * st.w[k][2] > 0 && along[0][i] + along[1][j] + along[2][k] >= inward_limit) {
                  Real& c = first[i * BucketBuffer::stride_i + j * BucketBuffer::stride_j + k * L + lane::constraint];
                  c = std::max(c, marker);
                }
        }
        if (rigid) continue;  // rigid points carry no mass to the grid
        ScatterLanes lanes = scatter_lanes<Mode>(ps, p);
        // The tensor-product part: node += S·a + ∂xS·fx + ∂yS·fy + ∂zS·fz over the stencil's nodes.
        const auto scatter_tensor = [&](const auto& stencil, const ScatterLanes& l) __attribute__((always_inline)) {
          const auto& [a, fx, fy, fz, minus_volume] = l;
          // The rows bounded by the stencil's counts, the nodes along a row by a fixed count
          // (with_trip_count; a run-time bound there changed the rounding of the results).
          const int ni = nodes_along(stencil, 0), nj = nodes_along(stencil, 1);
          for (int i = 0; i < ni; ++i)
            for (int j = 0; j < nj; ++j) {
              Real* row = first + i * BucketBuffer::stride_i + j * BucketBuffer::stride_j;
              const Real wij = stencil.w[i][0] * stencil.w[j][1];
              if constexpr (Mode::force) {
                // Per row: node += wz·(wij a + dxij fx + dyij fy) + dwz·(wij fz).
                const NodeLanes row_w = plus_scaled(plus_scaled(scaled(wij, a), stencil.dw[i][0] * stencil.w[j][1], fx),
                                                    stencil.w[i][0] * stencil.dw[j][1], fy);
                const NodeLanes row_d = scaled(wij, fz);
                with_trip_count<N>(nodes_along(stencil, 2), [&](auto nk) __attribute__((always_inline)) {
                  for (int k = 0; k < nk; ++k)
                    store_lanes(row + k * L, plus_scaled(plus_scaled(load_lanes(row + k * L), stencil.w[k][2], row_w),
                                                         stencil.dw[k][2], row_d));
                });
              } else {
                const NodeLanes row_w = scaled(wij, a);
                with_trip_count<N>(nodes_along(stencil, 2), [&](auto nk) __attribute__((always_inline)) {
                  for (int k = 0; k < nk; ++k)
                    store_lanes(row + k * L, plus_scaled(load_lanes(row + k * L), stencil.w[k][2], row_w));
                });
              }
            }
        };
        if constexpr (Mode::force && Shape::smoothed_on_grid && !Shape::per_node_gradient) {
          if (stabilized) {
            // Stabilized DDMP (ddmp_stabilization.hpp) in two transfers instead of four: the α
            // part −V σ α∇S_i and the stabilization's local part −V σ_s (1 − α) ∇S_i are one
            // plain-gradient scatter of −V (α σ + (1 − α) σ_s); the smoothed parts of σ and
            // −σ_s one corner scatter of σ − σ_s.
            const ParticleSymTensor& stab = ps.ddmp_stabilization_stress[p];
            const auto& stress = ps.stress[p];
            SymTensor local, smoothed;
            for (int c = 0; c < 6; ++c) {
              local[c] = st.alpha * Real(stress[c]) + (1 - st.alpha) * Real(stab[c]);
              smoothed[c] = Real(stress[c]) - Real(stab[c]);
            }
            set_force_lanes(lanes, lanes.minus_volume, local);
            scatter_tensor(ddmp_plain_gradient_stencil(st, inv_h), lanes);
            scatter_ddmp_corner_stress(st, lanes.minus_volume, smoothed, buffer);
            continue;
          }
        }
        scatter_tensor(st, lanes);
        if constexpr (Mode::force && Shape::smoothed_on_grid)
          // DDMP on the grid (ddmp_grid.hpp): −(1 − α) S̃_j V σ to the cell's 8 corners j.
          scatter_ddmp_corner_stress(st, lanes.minus_volume, ps.stress[p].template cast<Real>(), buffer);
        if constexpr (Mode::force && Shape::per_node_gradient) {
          // DDMP's gradient part that is not a tensor product (Paper A Eq. 4, 7): the smoothed
          // part per point, or the sub-points' α part (shape_ddmp_subpoints.hpp).
          for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j)
              for (int k = 0; k < N; ++k) {
                Real* node = first + i * BucketBuffer::stride_i + j * BucketBuffer::stride_j + k * L;
                const Vec3& g = st.smoothed[(i * N + j) * N + k];
                store_lanes(node, plus_scaled(plus_scaled(plus_scaled(load_lanes(node), g[0], lanes.fx), g[1], lanes.fy),
                                              g[2], lanes.fz));
              }
        }
        }  // tensor-product stencils
      }
    }
  }
}

// Sums over a particle's stencil of the node lanes n_i of the bucket buffer:
// aw = Σ S_i n_i and, with gradients, ax = Σ ∂xS_i n_i, ay = Σ ∂yS_i n_i, az = Σ ∂zS_i n_i.
// Per row (i, j) first rw = Σ_k Sz_k n_k and rd = Σ_k Sz'_k n_k, then weighted by Sx, Sy.
struct Interpolation {
  NodeLanes aw, ax, ay, az;
};

// The sums over the first ni × nj × nk nodes of the stencil.
template <bool Gradient, int N>
[[gnu::always_inline]] inline Interpolation interpolate_box(const Stencil<N>& st, const BucketBuffer& buffer, int ni,
                                                            int nj, int nk) {
  const Real* first = buffer.data.data() + buffer.offset(st.base[0], st.base[1], st.base[2]);
  Interpolation out{};
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j < nj; ++j) {
      const Real* row = first + i * BucketBuffer::stride_i + j * BucketBuffer::stride_j;
      NodeLanes rw{}, rd{};
      for (int k = 0; k < nk; ++k) {
        const NodeLanes node = load_lanes(row + k * lane::count);
        rw = plus_scaled(rw, st.w[k][2], node);
        if constexpr (Gradient) rd = plus_scaled(rd, st.dw[k][2], node);
      }
      const Real wij = st.w[i][0] * st.w[j][1];
      out.aw = plus_scaled(out.aw, wij, rw);
      if constexpr (Gradient) {
        out.ax = plus_scaled(out.ax, st.dw[i][0] * st.w[j][1], rw);
        out.ay = plus_scaled(out.ay, st.w[i][0] * st.dw[j][1], rw);
        out.az = plus_scaled(out.az, wij, rd);
      }
    }
  return out;
}

template <bool Gradient, int N>
[[gnu::always_inline]] inline Interpolation interpolate(const Stencil<N>& st, const BucketBuffer& buffer) {
  return interpolate_box<Gradient>(st, buffer, N, N, N);
}

// A trimmed stencil: only the nodes that carry weight (stencil.hpp), each of the (N − 1)³
// count combinations with fixed trip counts, unrolled like the full stencil's loops (faster
// than run-time bounds, and the same rounding).
template <bool Gradient, int N>
[[gnu::always_inline]] inline Interpolation interpolate(const TrimmedStencil<N>& st, const BucketBuffer& buffer) {
  Interpolation out;
  with_trip_count<N>(st.count[0], [&](auto ni) __attribute__((always_inline)) {
    with_trip_count<N>(st.count[1], [&](auto nj) __attribute__((always_inline)) {
      with_trip_count<N>(st.count[2], [&](auto nk)
                             __attribute__((always_inline)) { out = interpolate_box<Gradient>(st, buffer, ni, nj, nk); });
    });
  });
  return out;
}

// DDMP: the tensor-product part (S, α∇S), then the gradient part per node (the smoothed
// part, or with sub-points their α part).
template <bool Gradient, class DdmpStencilType,
          class = std::enable_if_t<std::is_same_v<DdmpStencilType, DdmpStencil> ||
                                   std::is_same_v<DdmpStencilType, DdmpSubpointStencil>>>
[[gnu::always_inline]] inline Interpolation interpolate(const DdmpStencilType& st, const BucketBuffer& buffer) {
  Interpolation out = interpolate<Gradient, 4>(static_cast<const Stencil<4>&>(st), buffer);
  if constexpr (Gradient) {
    const Real* first = buffer.data.data() + buffer.offset(st.base[0], st.base[1], st.base[2]);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) {
          const NodeLanes node =
              load_lanes(first + i * BucketBuffer::stride_i + j * BucketBuffer::stride_j + k * lane::count);
          const Vec3& g = st.smoothed[(i * 4 + j) * 4 + k];
          out.ax = plus_scaled(out.ax, g[0], node);
          out.ay = plus_scaled(out.ay, g[1], node);
          out.az = plus_scaled(out.az, g[2], node);
        }
  }
  return out;
}

// A wide CPDI1 stencil: vertex by vertex, from the grid's nodes.
template <bool Gradient>
Interpolation interpolate_wide(const CpdiBoxStencil& st, const SparseGrid& grid) {
  Interpolation out{};
  for_each_cpdi_vertex_node(st, [&](int i, int j, int k, Real w, Real gx, Real gy, Real gz) {
    const Real* lanes = grid.node(i, j, k);
    if (!lanes) throw NumericalError("a CPDI domain reaches a grid node outside the active grid");
    const NodeLanes node = load_lanes(lanes);
    out.aw += w * node;
    if constexpr (Gradient) {
      out.ax += gx * node;
      out.ay += gy * node;
      out.az += gz * node;
    }
  });
  return out;
}

// CPDI1 (shape_cpdi.hpp): the dense box, node by node; a wide stencil from the grid.
template <bool Gradient>
[[gnu::always_inline]] inline Interpolation interpolate(const CpdiBoxStencil& st, const BucketBuffer& buffer) {
  if (st.wide) {
    if (!buffer.grid) throw NumericalError("internal: a wide CPDI stencil in a gather without the grid");
    return interpolate_wide<Gradient>(st, *buffer.grid);
  }
  constexpr int n = CpdiBoxStencil::n;
  const Real* first = buffer.data.data() + buffer.offset(st.base[0], st.base[1], st.base[2]);
  Interpolation out{};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const int e = CpdiBoxStencil::index(i, j, k);
        const NodeLanes node = load_lanes(first + i * BucketBuffer::stride_i + j * BucketBuffer::stride_j + k * lane::count);
        out.aw = plus_scaled(out.aw, st.w[e], node);
        if constexpr (Gradient) {
          out.ax = plus_scaled(out.ax, st.g[0][e], node);
          out.ay = plus_scaled(out.ay, st.g[1][e], node);
          out.az = plus_scaled(out.az, st.g[2][e], node);
        }
      }
  return out;
}

// One particle's fault, kept if it is the bucket's first.
inline void note_fault(BucketTally& t, ParticleFault f, uint32_t p) {
  if (t.fault == ParticleFault::none) t.fault = f, t.fault_particle = p;
}

// Step-wide inputs of a gather pass.
struct GatherParameters {
  Real h;             // cell size, m
  Real dt;            // s
  Real flip;          // FLIP share of the velocity update
  Vec3 gravity;       // m/s²
  Real min_jacobian;  // smallest J accepted
};

template <class Shape, class Mode>
void gather_bucket(const Bucket& b, const BodyRun* runs, Particles& ps, const BodyInfo* bodies,
                   const GatherParameters& par, const BucketBuffer& buffer, BucketTally& tally,
                   RunTally* run_tally) {
  const Real h = par.h, dt = par.dt, flip = par.flip;
  const Vec3& gravity = par.gravity;
  constexpr bool gradient = Mode::gradient_lane >= 0;
  const Real inv_h = 1 / h;
  tally = BucketTally{};
  tally.cell_min = {max_cell_coord, max_cell_coord, max_cell_coord};
  tally.cell_max = {-max_cell_coord, -max_cell_coord, -max_cell_coord};
  // Records the particle's new cell: the bucket's node box for the next step, the drift
  // that calls for a re-sort, and a particle that left the grid's coordinate range.
  auto track_cell = [&](uint32_t p, const Vec3& x) {
    for (int a = 0; a < 3; ++a)
      if (!(std::abs(x[a] * inv_h) < max_cell_coord)) {
        note_fault(tally, std::isfinite(x[a]) ? ParticleFault::left_grid : ParticleFault::not_finite, p);
        return;
      }
    const auto cell = cell_of(x, inv_h);
    for (int a = 0; a < 3; ++a) {
      tally.cell_min[a] = std::min(tally.cell_min[a], cell[a]);
      tally.cell_max[a] = std::max(tally.cell_max[a], cell[a]);
    }
    if (!ParticleBuckets::within_drift(b, cell)) tally.drifted = true;
    else tally.cells.add_cell(b, cell);
  };

  // Sums of the bucket, one lane per particle slot of a group, added up at the end.
  Pack kinetic{}, strain{}, gravity_power{}, dissipation{}, blend_dissipation{}, increment_energy{};
  for (uint32_t run_index = b.run_begin; run_index < b.run_end; ++run_index) {
    const BodyRun& run = runs[run_index - b.run_begin];
    if (buffer.field >= 0 && ps.contact_field[run.begin] != buffer.field) continue;  // another field's run
    const BodyInfo& body = bodies[run.body];
    RunTally& rt = run_tally[run_index - b.run_begin];
    rt = RunTally{};
    if (body.marked_once) continue;  // at rest, zero velocity: nothing to gather
    if (body.role != BodyRole::deformable) {
      // Rigid points move with their prescribed velocity; F and σ stay as they are.
      for (uint32_t p = run.begin; p < run.end; ++p) {
        if constexpr (Mode::velocity) ps.velocity[p] = body.velocity.template cast<ParticleReal>();
        if constexpr (Mode::position) {
          ps.position[p] += dt * body.velocity;
          track_cell(p, ps.position[p]);
        }
      }
      continue;
    }
    std::visit(
        [&](const auto& material) {
          // The model's history columns (material_history.hpp); none for most models.
          constexpr size_t history_count = history_size<std::decay_t<decltype(material)>>;
          Real* history_column[history_count > 0 ? history_count : 1] = {};
          for (size_t k = 0; k < history_count; ++k) history_column[k] = ps.history[body.history_columns[k]].values.data();
          // Wave speeds grow as J falls (never the other way), so the run's smallest J
          // gives its largest wave speed: one evaluation per run instead of per particle.
          Real min_j = std::numeric_limits<Real>::infinity();
          [[maybe_unused]] const bool stabilized = body.ddmp_stabilization.mu > 0;
          for (uint32_t g0 = run.begin; g0 < run.end; g0 += pack_width) {
            const int n = int(std::min<uint32_t>(pack_width, run.end - g0));
            // 0. The group's particle state, one particle per lane, read before the grid
            //    interpolation so the lane-by-lane stores have long landed when the packs
            //    are read back as vectors. Idle lanes (q ≥ n) hold zero mass and volume,
            //    F = I and σ = 0: they add nothing to any sum.
            Pack m{}, v[3] = {}, f_old[3][3], s[6] = {}, volume0{};
            Pack history[history_count > 0 ? history_count : 1] = {};
            for (int r = 0; r < 3; ++r)
              for (int c = 0; c < 3; ++c) f_old[r][c] = Pack{} + (r == c ? Real(1) : Real(0));
            for (int q = 0; q < n; ++q) {
              const uint32_t p = g0 + uint32_t(q);
              m[q] = ps.mass[p];
              if constexpr (Mode::velocity)
                for (int a = 0; a < 3; ++a) v[a][q] = ps.velocity[p][a];
              if constexpr (gradient) {
                const auto& F = ps.deformation[p];
                for (int r = 0; r < 3; ++r)
                  for (int c = 0; c < 3; ++c) f_old[r][c][q] = F(r, c);
                for (int c = 0; c < 6; ++c) s[c][q] = ps.stress[p][c];
                volume0[q] = ps.volume0[p];
                for (size_t k = 0; k < history_count; ++k) history[k][q] = history_column[k][p];
              }
            }
            // 1. Interpolate from the grid, particle by particle: new velocity, its change
            //    and the velocity gradient, into lane q of the group's packs.
            //    The group's stencils first: eight independent computations the CPU
            //    overlaps, instead of each one's latency ahead of its particle's sums.
            Pack v_grid[3] = {}, dv[3] = {}, grad_v[3][3] = {};
            decltype(particle_stencil<Shape, gradient>(ps, g0, h, buffer)) stencils[pack_width];
            for (int q = 0; q < n; ++q) stencils[q] = particle_stencil<Shape, gradient>(ps, g0 + uint32_t(q), h, buffer);
            for (int q = 0; q < n; ++q) {
              const auto& st = stencils[q];
              // Stabilized DDMP reads the plain gradient L = Σ v ⊗ ∇S_i (ddmp_stabilization.hpp)
              // in the same sums, and its α part as α L: one interpolation instead of two.
              constexpr bool grid_ddmp = gradient && Shape::smoothed_on_grid && !Shape::per_node_gradient;
              const bool plain_gradient = grid_ddmp && stabilized;
              const auto [aw, ax, ay, az] = [&] {
                if constexpr (grid_ddmp)
                  if (plain_gradient) return interpolate<gradient>(ddmp_plain_gradient_stencil(st, inv_h), buffer);
                return interpolate<gradient>(st, buffer);
              }();
              // The point's L in scalars, written to its lane of the packs once at the end (a
              // lane of a pack read and written back per term cost more than the terms).
              [[maybe_unused]] Real l[3][3];
              for (int a = 0; a < 3; ++a) {
                v_grid[a][q] = aw[lane::momentum + a];
                dv[a][q] = aw[lane::force + a];
                if constexpr (gradient) {  // L_ab = Σ v_a ∂_b S
                  l[a][0] = ax[Mode::gradient_lane + a];
                  l[a][1] = ay[Mode::gradient_lane + a];
                  l[a][2] = az[Mode::gradient_lane + a];
                }
              }
              if constexpr (gradient && Shape::smoothed_on_grid) {
                // DDMP on the grid: + (1 − α) Σ_j S̃_j L_j, the nodal L of ddmp_grid.hpp.
                Real smoothed[9];
                ddmp_corner_velocity_gradient(st, buffer, smoothed);
                const auto add_smoothed = [&] {
                  for (int r = 0; r < 3; ++r)
                    for (int c = 0; c < 3; ++c) l[r][c] += smoothed[r * 3 + c];
                };
                if constexpr (!grid_ddmp) {
                  add_smoothed();
                } else if (!plain_gradient) {
                  add_smoothed();
                } else {
                  // The α part α Σ v ⊗ ∇S_i of the plain gradient, then σ_s from the plain
                  // gradient against L̄ (ddmp_stabilization.hpp).
                  Real plain_l[3][3];
                  for (int r = 0; r < 3; ++r)
                    for (int c = 0; c < 3; ++c) {
                      plain_l[r][c] = l[r][c];
                      l[r][c] = st.alpha * l[r][c] + smoothed[r * 3 + c];
                    }
                  update_ddmp_stabilization_stress(body.ddmp_stabilization, plain_l, l, dt,
                                                   ps.ddmp_stabilization_stress[g0 + uint32_t(q)]);
                }
              }
              if constexpr (gradient)
                for (int r = 0; r < 3; ++r)
                  for (int c = 0; c < 3; ++c) grad_v[r][c][q] = l[r][c];
            }
            // 2. Update the group's particles together, one per lane.
            if constexpr (Mode::velocity) {
              Pack flip_speed_sq{};
              increment_energy += Real(0.5) * m * (dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]);
              for (int a = 0; a < 3; ++a) {
                const Pack v_flip = v[a] + dv[a];
                flip_speed_sq += v_flip * v_flip;
                v[a] = flip * v_flip + (1 - flip) * v_grid[a];
              }
              const Pack speed_sq = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
              kinetic += Real(0.5) * m * speed_sq;
              blend_dissipation += Real(0.5) * m * (flip_speed_sq - speed_sq);
              for (int q = 0; q < n; ++q) {
                ps.velocity[g0 + q] = ParticleVec3(v[0][q], v[1][q], v[2][q]);
                tally.max_speed_sq = std::max(tally.max_speed_sq, speed_sq[q]);
                if (!std::isfinite(speed_sq[q])) note_fault(tally, ParticleFault::not_finite, g0 + q);
              }
            }
            if constexpr (Mode::position) {
              for (int a = 0; a < 3; ++a) gravity_power += (gravity[a] * m) * v_grid[a];
              for (int q = 0; q < n; ++q) {
                const uint32_t p = g0 + uint32_t(q);
                // In registers, then stored once: re-reading the freshly stored components
                // as one vector would stall on store forwarding.
                const Vec3 x = ps.position[p] + dt * Vec3(v_grid[0][q], v_grid[1][q], v_grid[2][q]);
                ps.position[p] = x;
                rt.mass_position += m[q] * x;
                rt.mass += m[q];
                track_cell(p, x);
              }
            }
            if constexpr (gradient) {
              Deformation<Pack> d;
              d.dt = dt;
              for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) d.velocity_gradient[r][c] = grad_v[r][c];
              // F ← (I + dt L) F
              auto& F = d.f_new;
              for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                  F[r][c] = f_old[r][c] + dt * (grad_v[r][0] * f_old[0][c] + grad_v[r][1] * f_old[1][c] +
                                                grad_v[r][2] * f_old[2][c]);
              d.jacobian = determinant(F);
              d.jacobian_old = determinant(f_old);  // dropped by the compiler where no model reads it
              update_material_stress(material, d, s, history);
              const Pack energy = volume0 * material_energy_density(material, d, s, history);
              strain += energy;
              if constexpr (has_dissipation_history<std::decay_t<decltype(material)>>::value)
                dissipation += volume0 * material_dissipation_density(material, history);
              for (int q = 0; q < n; ++q) {
                const uint32_t p = g0 + uint32_t(q);
                const Real J = d.jacobian[q];
                if (!(J > par.min_jacobian))
                  note_fault(tally, std::isfinite(J) ? ParticleFault::inverted : ParticleFault::not_finite, p);
                if (!std::isfinite(energy[q])) note_fault(tally, ParticleFault::not_finite, p);
                if constexpr (Shape::smoothed_on_grid && !Shape::per_node_gradient)
                  if (stabilized)  // booked as strain energy (ddmp_stabilization.hpp)
                    strain[q] += volume0[q] * ddmp_stabilization_energy_density(body.ddmp_stabilization,
                                                                                ps.ddmp_stabilization_stress[p], J);
                min_j = std::min(min_j, J);
                ParticleMat3& Fp = ps.deformation[p];
                for (int r = 0; r < 3; ++r)
                  for (int c = 0; c < 3; ++c) Fp(r, c) = F[r][c][q];
                for (int c = 0; c < 6; ++c) ps.stress[p][c] = s[c][q];
                for (size_t k = 0; k < history_count; ++k) history_column[k][p] = history[k][q];
              }
            }
          }
          if constexpr (gradient)
            if (run.end > run.begin)
              tally.max_wave_speed_sq = std::max(tally.max_wave_speed_sq, material.wave_speed_squared(min_j));
        },
        body.model);
  }
  for (int q = 0; q < pack_width; ++q) {
    tally.kinetic += kinetic[q];
    tally.strain += strain[q];
    tally.dissipation += dissipation[q];
    tally.blend_dissipation += blend_dissipation[q];
    tally.increment_energy += increment_energy[q];
    tally.gravity_power += gravity_power[q];
  }
}

}  // namespace latmpm::mpm
