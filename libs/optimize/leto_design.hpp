// LETO's design variables, paper C Sec. 3.1 and 4.1: per carrier particle its density ρ_c
// (bounds [0, 1], step ≤ 0.5 per iteration) and its position (in-plane components when
// planar; bounds: the design domain; step ≤ 2 cells per iteration), mapped to the
// quadrature densities by CarrierTransfer. x = [ρ_1 … ρ_N, x_1 … x_N (d each)].
#pragma once
#include "optimize/carrier_transfer.hpp"
#include "optimize/parameterisation.hpp"
#include "optimize/sharpening.hpp"

namespace latmpm::optimize {

struct LetoSettings {
  Real kernel_radius_cells = 1.5;  // H / h
  Real clamp_knee = 0.9;           // where the smooth clamp leaves the identity
  Real density_move = 0.5;         // paper C Sec. 4.1
  Real carrier_density_max = 2;    // upper bound of ρ_c (the clamp keeps every ρ_q ≤ 1)
  Real position_move_cells = 0.5;  // paper C Sec. 4.1 says 2 (with adaptive asymptotes; docs/paper-c.md)
  // Eq. (38)'s sharpening of the quadrature densities (sharpening.hpp), for LETO without
  // the narrow band: β from 1.01 to sharpen_end over sharpen_ramp iterations; 0: off.
  Real sharpen_end = 0;
  int sharpen_ramp = 90;
};

class LetoDesign final : public Parameterisation {
 public:
  LetoDesign(const DesignGrid& grid, const LetoSettings& settings, Real volume_fraction);
  std::string name() const override { return "leto"; }
  std::vector<Real> initial() const override;
  void bounds(std::vector<Real>& lower, std::vector<Real>& upper, std::vector<Real>& move) const override;
  void densities(const std::vector<Real>& x, std::vector<Real>& density) override;
  std::vector<Real> pull_back(const std::vector<Real>& x, const std::vector<Real>& d_density) const override;
  void start_iteration(int k) override;
  bool continuation_done() const override;

  Carriers carriers(const std::vector<Real>& x) const;

 private:
  DesignGrid grid_;
  LetoSettings settings_;
  CarrierTransfer transfer_;
  Carriers initial_;
  std::vector<Real> kernel_sum_;  // of the last densities() call
  std::vector<Real> clamped_;     // ρ_q before the sharpening, of the last densities() call
  Sharpening sharpening_;
  int iteration_ = 0;
};

}  // namespace latmpm::optimize
