// Node-wise stages of a step on the sparse grid: the velocity update with forces and
// boundary conditions, the reactions those conditions need, and small lane operations the
// update schemes use.
#pragma once
#include <vector>

#include "mpm/sparse_grid.hpp"
#include "mpm/transfer.hpp"

namespace latmpm::mpm {

// Per constrained body: the force its constraint applies to the model (N), and the power
// of that force at the prescribed velocity (W).
struct Reactions {
  std::vector<Vec3> force;
  std::vector<Real> power;
};

// Explicit update of every node (Paper B Eq. 5): v_old = p/m, f = f_int + m g,
// v_new = v_old + dt f/m — or, on a node touched by a fixed or driven body, the prescribed
// velocity, with the reaction r = (m v_prescribed − p)/dt − f that enforcing it takes; on a
// node of a slipping held face (BodyInfo::hold_slip), the free update less its component
// along the face normal, with the reaction computed the same way.
// Before: lanes m, p, f, constraint. After: m, v_new, v_new − v_old, constraint.
// Returns the reactions per block, a row of 4 values per body (r_x, r_y, r_z in N, power in
// W), for the caller to sum in block order (Domain::sum_in_order, then reactions_from_sums).
std::vector<Real> update_grid_velocities(SparseGrid& grid, Real dt, const Vec3& gravity,
                                         const std::vector<BodyInfo>& bodies);
// Per block, Σ ½ m_I |Δv_I|² over its nodes (J), the lanes after the node update (m, v_new,
// Δv = v_new − v_old): the kinetic energy the velocity increments carry on the grid, for the
// caller to sum in block order. The points receive Σ_p ½ m_p |Σ_I S_Ip Δv_I|² of it
// (transfer.hpp, BucketTally::increment_energy); twice the difference is the FLIP update's
// projection loss (StepDiagnostics::transfer_dissipation).
std::vector<Real> node_increment_energy_rows(SparseGrid& grid);
// The per-body totals of such sums: force from values 4b..4b+2, power from 4b+3.
Reactions reactions_from_sums(const std::vector<Real>& sums);

// v = p/m with the boundary conditions applied, from lanes [from, from+3) into
// [to, to+3) (MUSL's remapped velocity, USF's velocity before the forces).
void grid_velocity_from_momentum(SparseGrid& grid, int from, int to, const std::vector<BodyInfo>& bodies);

// Zeroes lanes [first, first + count) of every node.
void clear_grid_lanes(SparseGrid& grid, int first, int count);
void clear_grid(SparseGrid& grid);

}  // namespace latmpm::mpm
