// The design domain of a topology optimisation (paper C Sec. 2.2, 3.3): a box of cells of
// size h on the MPM background grid, each cell sampled by n×n(×n) uniformly placed
// quadrature points (the multi-density points: each carries its own density). The
// quadrature points form a regular lattice of spacing s = h/n, which the narrow-band graph
// (Sec. 3.4) and the refined evaluation (Sec. 4.2: one refined cell per quadrature point)
// use directly. A planar (2D) domain is one cell thick along z with one quadrature layer;
// its points carry the area s² times the slab thickness, and z displacements are held.
#pragma once
#include <Eigen/Core>
#include <cstddef>

#include "mpm/real.hpp"

namespace latmpm::optimize {

using mpm::Real;
using mpm::Vec3;
using Index3 = Eigen::Vector3i;

struct DesignGrid {
  Real cell_size = 0;          // h, m
  Index3 cells{0, 0, 0};       // cells per axis (cells[2] == 1 when planar)
  int per_cell = 2;            // quadrature points per cell and axis (in-plane when planar)
  bool planar = false;         // 2D: plane strain slab of thickness `thickness`
  Real thickness = 0;          // m, planar only

  int dimension() const { return planar ? 2 : 3; }
  Real spacing() const { return cell_size / per_cell; }  // s, m
  // Quadrature lattice size per axis.
  Index3 lattice() const { return {cells[0] * per_cell, cells[1] * per_cell, planar ? 1 : cells[2] * per_cell}; }
  size_t point_count() const;
  size_t index(const Index3& l) const {
    const Index3 n = lattice();
    return size_t(l[0]) + size_t(n[0]) * (size_t(l[1]) + size_t(n[1]) * size_t(l[2]));
  }
  Index3 lattice_coord(size_t q) const;
  bool inside(const Index3& l) const;
  // Reference position of point q (m): ((l + ½) s), at mid-thickness of the cell when planar.
  Vec3 position(size_t q) const;
  // The cell holding point q.
  Index3 cell_of(size_t q) const;
  Real point_volume() const;   // m³ (planar: s² × thickness)
  Real domain_volume() const;  // m³
  Vec3 extent() const;         // m, the box [0, extent)

  // The grid refined `factor` times: cell h/factor, the same points per cell, so that with
  // factor == per_cell every quadrature point of this grid becomes one refined cell.
  DesignGrid refined(int factor) const;
};

}  // namespace latmpm::optimize
