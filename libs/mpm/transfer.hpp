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
#include "mpm/material_model.hpp"
#include "mpm/node_lanes.hpp"
#include "mpm/particles.hpp"
#include "mpm/shape_functions.hpp"

namespace latmpm::mpm {

// What the transfers need to know of a body.
struct BodyInfo {
  BodyRole role = BodyRole::deformable;
  Vec3 velocity = Vec3::Zero();  // prescribed velocity of a driven body, m/s
  MaterialModel model;
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
  Real record_stress_volume = 0, record_volume = 0;
  Real max_speed_sq = 0;  // m²/s²
  Real max_wave_speed_sq = 0;  // m²/s², from the smallest J of each run (see below)
  std::array<int, 3> cell_min{}, cell_max{};
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
    Vec3 l = ps.half_size0[p];
    if constexpr (Shape::stretches_with_f) l = l.cwiseProduct(ps.deformation[p].diagonal().cwiseAbs());
    for (int a = 0; a < 3; ++a) l[a] = std::clamp(l[a], Real(1e-3) * h, Shape::max_half * h);
    return l;
  }
}

template <class Shape, class Mode>
void scatter_bucket(const Bucket& b, const BodyRun* runs, const Particles& ps,
                    const BodyInfo* bodies, Real h, BucketBuffer& buffer) {
  constexpr int N = Shape::nodes_per_axis;
  constexpr int L = lane::count;
  const Real inv_h = 1 / h;
  for (uint32_t r = b.run_begin; r < b.run_end; ++r) {
    const BodyRun& run = runs[r - b.run_begin];
    const bool rigid = bodies[run.body].role != BodyRole::deformable;
    if (rigid && !Mode::constraint) continue;
    for (uint32_t p = run.begin; p < run.end; ++p) {
      const auto st = make_stencil<Shape>(ps.position[p], stencil_half_size<Shape>(ps, p, h), inv_h);
      Real* first = buffer.data.data() + buffer.offset(st.base[0], st.base[1], st.base[2]);
      if (rigid) {
        // Rigid points carry no mass to the grid; they mark the nodes they touch.
        const Real marker = Real(run.body + 1);
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < N; ++j)
            for (int k = 0; k < N; ++k)
              if (st.w[i][0] * st.w[j][1] * st.w[k][2] > 0) {
                Real& c = first[i * BucketBuffer::stride_i + j * BucketBuffer::stride_j + k * L + lane::constraint];
                c = std::max(c, marker);
              }
        continue;
      }
      // Lane vectors: node += S·a + ∂xS·fx + ∂yS·fy + ∂zS·fz.
      NodeLanes a{}, fx{}, fy{}, fz{};
      const Real m = ps.mass[p];
      if constexpr (Mode::mass) a[lane::mass] = m;
      if constexpr (Mode::momentum_lane >= 0)
        for (int c = 0; c < 3; ++c) a[Mode::momentum_lane + c] = m * ps.velocity[p][c];
      if constexpr (Mode::force) {
        // f_i = −V σ ∇S_i with V = J V0 the current volume.
        const Real v = -ps.volume0[p] * ps.deformation[p].determinant();
        const SymTensor& s = ps.stress[p];
        fx[lane::force] = v * s[0], fx[lane::force + 1] = v * s[5], fx[lane::force + 2] = v * s[4];
        fy[lane::force] = v * s[5], fy[lane::force + 1] = v * s[1], fy[lane::force + 2] = v * s[3];
        fz[lane::force] = v * s[4], fz[lane::force + 1] = v * s[3], fz[lane::force + 2] = v * s[2];
      }
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
          Real* row = first + i * BucketBuffer::stride_i + j * BucketBuffer::stride_j;
          const Real wij = st.w[i][0] * st.w[j][1];
          if constexpr (Mode::force) {
            // Per row: node += wz·(wij a + dxij fx + dyij fy) + dwz·(wij fz).
            const NodeLanes row_w = wij * a + (st.dw[i][0] * st.w[j][1]) * fx + (st.w[i][0] * st.dw[j][1]) * fy;
            const NodeLanes row_d = wij * fz;
            for (int k = 0; k < N; ++k)
              store_lanes(row + k * L, load_lanes(row + k * L) + st.w[k][2] * row_w + st.dw[k][2] * row_d);
          } else {
            const NodeLanes row_w = wij * a;
            for (int k = 0; k < N; ++k) store_lanes(row + k * L, load_lanes(row + k * L) + st.w[k][2] * row_w);
          }
        }
    }
  }
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
  constexpr int N = Shape::nodes_per_axis;
  constexpr int L = lane::count;
  constexpr bool gradient = Mode::gradient_lane >= 0;
  const Real inv_h = 1 / h;
  tally = BucketTally{};
  tally.cell_min = {max_cell_coord, max_cell_coord, max_cell_coord};
  tally.cell_max = {-max_cell_coord, -max_cell_coord, -max_cell_coord};
  // Records the particle's new cell: the bucket's node box for the next step, the drift
  // that calls for a re-sort, and a particle that left the grid's coordinate range.
  auto track_cell = [&](uint32_t p) {
    for (int a = 0; a < 3; ++a)
      if (!(std::abs(ps.position[p][a] * inv_h) < max_cell_coord)) {
        note_fault(tally, std::isfinite(ps.position[p][a]) ? ParticleFault::left_grid : ParticleFault::not_finite, p);
        return;
      }
    const auto cell = cell_of(ps.position[p], inv_h);
    for (int a = 0; a < 3; ++a) {
      tally.cell_min[a] = std::min(tally.cell_min[a], cell[a]);
      tally.cell_max[a] = std::max(tally.cell_max[a], cell[a]);
    }
    if (!ParticleBuckets::within_drift(b, cell)) tally.drifted = true;
  };

  for (uint32_t r = b.run_begin; r < b.run_end; ++r) {
    const BodyRun& run = runs[r - b.run_begin];
    const BodyInfo& body = bodies[run.body];
    RunTally& rt = run_tally[r - b.run_begin];
    rt = RunTally{};
    if (body.role != BodyRole::deformable) {
      // Rigid points move with their prescribed velocity; F and σ stay as they are.
      for (uint32_t p = run.begin; p < run.end; ++p) {
        if constexpr (Mode::velocity) ps.velocity[p] = body.velocity;
        if constexpr (Mode::position) {
          ps.position[p] += dt * body.velocity;
          track_cell(p);
        }
      }
      continue;
    }
    std::visit(
        [&](const auto& material) {
          // Wave speeds grow as J falls (never the other way), so the run's smallest J
          // gives its largest wave speed: one evaluation per run instead of per particle.
          Real min_j = std::numeric_limits<Real>::infinity();
          for (uint32_t p = run.begin; p < run.end; ++p) {
            const auto st = make_stencil<Shape>(ps.position[p], stencil_half_size<Shape>(ps, p, h), inv_h);
            const Real* first = buffer.data.data() + buffer.offset(st.base[0], st.base[1], st.base[2]);
            // Sums over the stencil: aw = Σ S_i n_i, ax = Σ ∂xS_i n_i, ... for node lanes n_i.
            // Per row (i, j): rw = Σ_k Sz_k n_k and rd = Σ_k Sz_k n_k, then weighted by Sx, Sy.
            NodeLanes aw{}, ax{}, ay{}, az{};
            for (int i = 0; i < N; ++i)
              for (int j = 0; j < N; ++j) {
                const Real* row = first + i * BucketBuffer::stride_i + j * BucketBuffer::stride_j;
                NodeLanes rw{}, rd{};
                for (int k = 0; k < N; ++k) {
                  const NodeLanes n = load_lanes(row + k * L);
                  rw += st.w[k][2] * n;
                  if constexpr (gradient) rd += st.dw[k][2] * n;
                }
                const Real wij = st.w[i][0] * st.w[j][1];
                aw += wij * rw;
                if constexpr (gradient) {
                  ax += (st.dw[i][0] * st.w[j][1]) * rw;
                  ay += (st.w[i][0] * st.dw[j][1]) * rw;
                  az += wij * rd;
                }
              }
            const Real m = ps.mass[p];
            const Vec3 v_grid(aw[lane::momentum], aw[lane::momentum + 1], aw[lane::momentum + 2]);
            if constexpr (Mode::velocity) {
              const Vec3 dv(aw[lane::force], aw[lane::force + 1], aw[lane::force + 2]);
              Vec3& v = ps.velocity[p];
              v = flip * (v + dv) + (1 - flip) * v_grid;
              const Real speed_sq = v.squaredNorm();
              tally.kinetic += Real(0.5) * m * speed_sq;
              tally.max_speed_sq = std::max(tally.max_speed_sq, speed_sq);
              if (!std::isfinite(speed_sq)) note_fault(tally, ParticleFault::not_finite, p);
            }
            if constexpr (Mode::position) {
              ps.position[p] += dt * v_grid;
              tally.gravity_power += m * gravity.dot(v_grid);
              rt.mass_position += m * ps.position[p];
              rt.mass += m;
              track_cell(p);
            }
            if constexpr (gradient) {
              constexpr int g = Mode::gradient_lane;
              Mat3 grad_v;  // L_ab = Σ v_a ∂_b S
              grad_v << ax[g], ay[g], az[g], ax[g + 1], ay[g + 1], az[g + 1], ax[g + 2], ay[g + 2], az[g + 2];
              // F ← F + dt L F, written out: Eigen's aliasing-safe product costs a temporary.
              Mat3& F = ps.deformation[p];
              const Mat3 F_old = F;
              for (int row = 0; row < 3; ++row)
                for (int col = 0; col < 3; ++col)
                  F(row, col) += dt * (grad_v(row, 0) * F_old(0, col) + grad_v(row, 1) * F_old(1, col) +
                                       grad_v(row, 2) * F_old(2, col));
              const Real J = F.determinant();
              if (!(J > par.min_jacobian))
                note_fault(tally, std::isfinite(J) ? ParticleFault::inverted : ParticleFault::not_finite, p);
              SymTensor& s = ps.stress[p];
              material.update_stress(Deformation{grad_v, F, J, dt}, s);
              const Real energy = ps.volume0[p] * material.strain_energy_density(F, J, s);
              if (!std::isfinite(energy)) note_fault(tally, ParticleFault::not_finite, p);
              tally.strain += energy;
              min_j = std::min(min_j, J);
              if (ps.flags[p] & Particles::record_flag) {
                const Real volume = J * ps.volume0[p];
                tally.record_stress_volume += s[2] * volume;
                tally.record_volume += volume;
              }
            }
          }
          if constexpr (gradient)
            if (run.end > run.begin)
              tally.max_wave_speed_sq = std::max(tally.max_wave_speed_sq, material.wave_speed_squared(min_j));
        },
        body.model);
  }
}

}  // namespace latmpm::mpm
