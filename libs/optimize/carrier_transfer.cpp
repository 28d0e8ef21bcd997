#include "optimize/carrier_transfer.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace latmpm::optimize {

Carriers carriers_on_quadrature(const DesignGrid& grid, Real volume_fraction) {
  Carriers c;
  const size_t n = grid.point_count();
  c.position.resize(n);
  for (size_t q = 0; q < n; ++q) c.position[q] = grid.position(q);
  c.density.assign(n, volume_fraction);
  return c;
}

CarrierTransfer::CarrierTransfer(const DesignGrid& grid, Real kernel_radius, SmoothClamp clamp)
    : grid_(grid), kernel_{kernel_radius, grid.dimension()}, clamp_(clamp) {}

template <class F>
void CarrierTransfer::for_neighbours(const Vec3& x, F&& f) const {
  const Real s = grid_.spacing(), H = kernel_.radius;
  const Index3 n = grid_.lattice();
  Index3 lo, hi;
  for (int a = 0; a < 3; ++a) {
    if (a == 2 && grid_.planar) {
      lo[a] = hi[a] = 0;
      continue;
    }
    // Lattice point l sits at (l + ½) s.
    lo[a] = std::max(0, int(std::ceil((x[a] - H) / s - 0.5)));
    hi[a] = std::min(n[a] - 1, int(std::floor((x[a] + H) / s - 0.5)));
  }
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const size_t q = grid_.index({i, j, k});
        Vec3 d = x - grid_.position(q);
        if (grid_.planar) d[2] = 0;
        const Real r = d.norm();
        if (r < H) f(q, d, r);
      }
}

void CarrierTransfer::densities(const Carriers& carriers, std::vector<Real>& kernel_sum,
                                std::vector<Real>& density) const {
  const Real V = grid_.spacing() * grid_.spacing() * (grid_.planar ? 1 : grid_.spacing());
  kernel_sum.assign(grid_.point_count(), 0);
  // Scatter in carrier order on one thread: the sums do not depend on the thread count.
  for (size_t c = 0; c < carriers.size(); ++c) {
    const Real m = V * carriers.density[c];
    for_neighbours(carriers.position[c], [&](size_t q, const Vec3&, Real r) { kernel_sum[q] += m * kernel_.value(r); });
  }
  density.resize(kernel_sum.size());
  for (size_t q = 0; q < kernel_sum.size(); ++q) density[q] = clamp_.value(kernel_sum[q]);
}

void CarrierTransfer::pull_back(const Carriers& carriers, const std::vector<Real>& kernel_sum,
                                const std::vector<Real>& d_density, std::vector<Real>& d_carrier_density,
                                std::vector<Vec3>& d_carrier_position) const {
  const Real V = grid_.spacing() * grid_.spacing() * (grid_.planar ? 1 : grid_.spacing());
  d_carrier_density.assign(carriers.size(), 0);
  d_carrier_position.assign(carriers.size(), Vec3::Zero());
  tbb::parallel_for(size_t(0), carriers.size(), [&](size_t c) {
    Real dr = 0;
    Vec3 dx = Vec3::Zero();
    for_neighbours(carriers.position[c], [&](size_t q, const Vec3& d, Real r) {
      const Real g = d_density[q] * clamp_.derivative(kernel_sum[q]) * V;
      if (g == 0) return;
      dr += g * kernel_.value(r);
      if (r > 0) dx += g * carriers.density[c] * kernel_.derivative(r) / r * d;
    });
    d_carrier_density[c] = dr;
    d_carrier_position[c] = dx;
  });
}

}  // namespace latmpm::optimize
