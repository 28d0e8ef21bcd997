// LETO's design variables and their transfer to the quadrature points (C2P), paper C
// Sec. 3.1: carrier particles with position x_c and density ρ_c move freely over the design
// domain; each quadrature point q gets
//   ρ̃_q = Σ_c V ρ_c W(|x_q − x_c|, H)     (Eq. 7, V = the quadrature volume s^d)
//   ρ_q = c(ρ̃_q)                           (Eq. 11, 13: the smooth clamp)
// and back (P2C) the chain rule of Eq. (9), (10), (12), (14):
//   ∂J/∂ρ_c = Σ_q ∂J/∂ρ_q c'(ρ̃_q) V W_qc,
//   ∂J/∂x_c = Σ_q ∂J/∂ρ_q c'(ρ̃_q) V ρ_c W'(r_qc) (x_c − x_q)/r_qc.
// The quadrature points sit on a lattice, so a carrier's neighbours are the lattice points
// in the box of half-width H around it: no search structure is needed.
#pragma once
#include <vector>

#include "optimize/design_grid.hpp"
#include "optimize/smooth_clamp.hpp"
#include "optimize/sph_kernel.hpp"

namespace latmpm::optimize {

struct Carriers {
  std::vector<Vec3> position;  // m (z at mid-thickness when planar)
  std::vector<Real> density;   // dimensionless

  size_t size() const { return density.size(); }
};

// One carrier on every quadrature point with the density that gives every point ρ ≈
// `volume_fraction` (Sec. 3.1, step 0).
Carriers carriers_on_quadrature(const DesignGrid& grid, Real volume_fraction);

class CarrierTransfer {
 public:
  // kernel_radius: H (m); clamp: the smooth clamp's knee.
  CarrierTransfer(const DesignGrid& grid, Real kernel_radius, SmoothClamp clamp);

  const CubicSplineKernel& kernel() const { return kernel_; }
  // ρ̃ (the kernel sums) and ρ (clamped) of every quadrature point.
  void densities(const Carriers& carriers, std::vector<Real>& kernel_sum, std::vector<Real>& density) const;
  // Given ∂J/∂ρ_q and the kernel sums of the same carriers: ∂J/∂ρ_c and ∂J/∂x_c (only the
  // in-plane components when planar).
  void pull_back(const Carriers& carriers, const std::vector<Real>& kernel_sum,
                 const std::vector<Real>& d_density, std::vector<Real>& d_carrier_density,
                 std::vector<Vec3>& d_carrier_position) const;

 private:
  template <class F>
  void for_neighbours(const Vec3& x, F&& f) const;

  DesignGrid grid_;
  CubicSplineKernel kernel_;
  SmoothClamp clamp_;
};

}  // namespace latmpm::optimize
