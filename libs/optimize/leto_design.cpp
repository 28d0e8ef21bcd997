#include "optimize/leto_design.hpp"

#include <algorithm>

namespace latmpm::optimize {

LetoDesign::LetoDesign(const DesignGrid& grid, const LetoSettings& settings, Real volume_fraction)
    : grid_(grid), settings_(settings),
      transfer_(grid, settings.kernel_radius_cells * grid.cell_size, SmoothClamp{settings.clamp_knee}),
      initial_(carriers_on_quadrature(grid, volume_fraction)) {}

std::vector<Real> LetoDesign::initial() const {
  std::vector<Real> x(initial_.density);
  for (const Vec3& p : initial_.position)
    for (int a = 0; a < grid_.dimension(); ++a) x.push_back(p[a]);
  return x;
}

void LetoDesign::bounds(std::vector<Real>& lower, std::vector<Real>& upper, std::vector<Real>& move) const {
  const size_t n = initial_.size();
  const int d = grid_.dimension();
  lower.assign(n, 0);
  upper.assign(n, settings_.carrier_density_max);
  move.assign(n, settings_.density_move);
  const Vec3 extent = grid_.extent();
  for (size_t c = 0; c < n; ++c)
    for (int a = 0; a < d; ++a) {
      lower.push_back(0);
      upper.push_back(extent[a]);
      move.push_back(settings_.position_move_cells * grid_.cell_size);
    }
}

Carriers LetoDesign::carriers(const std::vector<Real>& x) const {
  Carriers c = initial_;
  const size_t n = c.size();
  const int d = grid_.dimension();
  for (size_t i = 0; i < n; ++i) {
    c.density[i] = x[i];
    for (int a = 0; a < d; ++a) c.position[i][a] = x[n + size_t(d) * i + size_t(a)];
  }
  return c;
}

void LetoDesign::start_iteration(int k) {
  iteration_ = k;
  if (settings_.sharpen_end > 0) {
    const Real t = std::min(Real(1), Real(k) / Real(std::max(1, settings_.sharpen_ramp)));
    sharpening_.beta = 1.01 + t * (settings_.sharpen_end - 1.01);
  }
}

bool LetoDesign::continuation_done() const {
  return settings_.sharpen_end <= 0 || iteration_ >= settings_.sharpen_ramp;
}

void LetoDesign::densities(const std::vector<Real>& x, std::vector<Real>& density) {
  transfer_.densities(carriers(x), kernel_sum_, density);
  if (settings_.sharpen_end <= 0) return;
  clamped_ = density;
  for (size_t q = 0; q < density.size(); ++q) density[q] = sharpening_.value(clamped_[q]);
}

std::vector<Real> LetoDesign::pull_back(const std::vector<Real>& x, const std::vector<Real>& d_density) const {
  const Carriers c = carriers(x);
  std::vector<Real> d_rho;
  std::vector<Vec3> d_pos;
  if (settings_.sharpen_end > 0) {
    std::vector<Real> d_clamped(d_density);
    for (size_t q = 0; q < d_clamped.size(); ++q) d_clamped[q] *= sharpening_.derivative(clamped_[q]);
    transfer_.pull_back(c, kernel_sum_, d_clamped, d_rho, d_pos);
  } else {
    transfer_.pull_back(c, kernel_sum_, d_density, d_rho, d_pos);
  }
  std::vector<Real> g(d_rho);
  for (const Vec3& v : d_pos)
    for (int a = 0; a < grid_.dimension(); ++a) g.push_back(v[a]);
  return g;
}

}  // namespace latmpm::optimize
