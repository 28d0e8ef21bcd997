#include "optimize/simp_design.hpp"

#include <algorithm>
#include <cmath>

namespace latmpm::optimize {

SimpDesign::SimpDesign(const DesignGrid& grid, const SimpSettings& settings, Real volume_fraction)
    : grid_(grid), settings_(settings), volume_fraction_(volume_fraction) {
  const Index3 c = grid.cells;
  cell_count_ = size_t(c[0]) * size_t(c[1]) * size_t(c[2]);
  auto cell_index = [&](const Index3& e) { return size_t(e[0]) + size_t(c[0]) * (size_t(e[1]) + size_t(c[1]) * size_t(e[2])); };
  cell_of_point_.resize(grid.point_count());
  for (size_t q = 0; q < grid.point_count(); ++q) cell_of_point_[q] = cell_index(grid.cell_of(q));
  const Real r = settings.filter_radius_cells;
  const int reach = int(std::ceil(r));
  filter_offset.push_back(0);
  for (int k = 0; k < c[2]; ++k)
    for (int j = 0; j < c[1]; ++j)
      for (int i = 0; i < c[0]; ++i) {
        Real sum = 0;
        const size_t first = filter_cell.size();
        for (int dk = -reach; dk <= reach; ++dk)
          for (int dj = -reach; dj <= reach; ++dj)
            for (int di = -reach; di <= reach; ++di) {
              const Index3 e(i + di, j + dj, k + dk);
              if ((e.array() < 0).any() || (e.array() >= c.array()).any()) continue;
              const Real w = r - std::sqrt(Real(di * di + dj * dj + dk * dk));
              if (w <= 0) continue;
              filter_cell.push_back(cell_index(e));
              filter_weight.push_back(w);
              sum += w;
            }
        for (size_t m = first; m < filter_cell.size(); ++m) filter_weight[m] /= sum;
        filter_offset.push_back(filter_cell.size());
      }
}

std::vector<Real> SimpDesign::initial() const { return std::vector<Real>(cell_count_, volume_fraction_); }

void SimpDesign::bounds(std::vector<Real>& lower, std::vector<Real>& upper, std::vector<Real>& move) const {
  lower.assign(cell_count_, 0);
  upper.assign(cell_count_, 1);
  move.assign(cell_count_, settings_.move);
}

void SimpDesign::start_iteration(int k) {
  beta_ = std::min(settings_.beta_max, std::pow(2.0, Real(k / std::max(1, settings_.beta_every))));
}

void SimpDesign::densities(const std::vector<Real>& x, std::vector<Real>& density) {
  filtered_.assign(cell_count_, 0);
  for (size_t e = 0; e < cell_count_; ++e)
    for (size_t m = filter_offset[e]; m < filter_offset[e + 1]; ++m) filtered_[e] += filter_weight[m] * x[filter_cell[m]];
  const Real b = beta_, eta = settings_.eta;
  const Real den = std::tanh(b * eta) + std::tanh(b * (1 - eta));
  density.resize(cell_of_point_.size());
  for (size_t q = 0; q < density.size(); ++q)
    density[q] = (std::tanh(b * eta) + std::tanh(b * (filtered_[cell_of_point_[q]] - eta))) / den;
}

std::vector<Real> SimpDesign::pull_back(const std::vector<Real>& /*x*/, const std::vector<Real>& d_density) const {
  const Real b = beta_, eta = settings_.eta;
  const Real den = std::tanh(b * eta) + std::tanh(b * (1 - eta));
  std::vector<Real> d_projected(cell_count_, 0);
  for (size_t q = 0; q < d_density.size(); ++q) d_projected[cell_of_point_[q]] += d_density[q];
  std::vector<Real> d_filtered(cell_count_);
  for (size_t e = 0; e < cell_count_; ++e) {
    const Real t = std::tanh(b * (filtered_[e] - eta));
    d_filtered[e] = d_projected[e] * b * (1 - t * t) / den;
  }
  // The filter's transpose: each cell's weight row scattered back.
  std::vector<Real> g(cell_count_, 0);
  for (size_t e = 0; e < cell_count_; ++e)
    for (size_t m = filter_offset[e]; m < filter_offset[e + 1]; ++m) g[filter_cell[m]] += filter_weight[m] * d_filtered[e];
  return g;
}

}  // namespace latmpm::optimize
