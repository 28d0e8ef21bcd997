// The SIMP baseline of paper C Sec. 4.2: one density per cell, the density filter of
// Bruns & Tortorelli (weights max(0, r − |x_e − x_i|), r = 1.5 cells) and the smooth
// Heaviside projection of Wang, Lazarov & Sigmund (2011),
//   ρ̄ = (tanh(βη) + tanh(β(ρ̃ − η))) / (tanh(βη) + tanh(β(1 − η))),  η = ½,
// with β doubled every `beta_every` iterations up to `beta_max` (continuation). Every
// quadrature point of a cell takes the cell's projected density.
#pragma once
#include <vector>

#include "optimize/design_grid.hpp"
#include "optimize/parameterisation.hpp"

namespace latmpm::optimize {

struct SimpSettings {
  Real filter_radius_cells = 1.5;
  Real beta_max = 16;
  int beta_every = 25;
  Real move = 0.2;
  Real eta = 0.5;
};

class SimpDesign final : public Parameterisation {
 public:
  SimpDesign(const DesignGrid& grid, const SimpSettings& settings, Real volume_fraction);
  std::string name() const override { return "simp"; }
  std::vector<Real> initial() const override;
  void bounds(std::vector<Real>& lower, std::vector<Real>& upper, std::vector<Real>& move) const override;
  void start_iteration(int k) override;
  bool continuation_done() const override { return beta_ >= settings_.beta_max; }
  void densities(const std::vector<Real>& x, std::vector<Real>& density) override;
  std::vector<Real> pull_back(const std::vector<Real>& x, const std::vector<Real>& d_density) const override;

  Real beta() const { return beta_; }
  size_t cell_count() const { return cell_count_; }

 private:
  DesignGrid grid_;
  SimpSettings settings_;
  Real volume_fraction_;
  size_t cell_count_ = 0;
  std::vector<size_t> cell_of_point_;
  // Filter rows: cell e averages cells filter_cell[k] with weight filter_weight[k] for k in
  // [filter_offset[e], filter_offset[e+1]) (normalised).
  std::vector<size_t> filter_offset, filter_cell;
  std::vector<Real> filter_weight;
  Real beta_ = 1;
  std::vector<Real> filtered_;  // ρ̃ of the last densities() call
};

}  // namespace latmpm::optimize
