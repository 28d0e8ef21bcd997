#include "optimize/design_grid.hpp"

namespace latmpm::optimize {

size_t DesignGrid::point_count() const {
  const Index3 n = lattice();
  return size_t(n[0]) * size_t(n[1]) * size_t(n[2]);
}

Index3 DesignGrid::lattice_coord(size_t q) const {
  const Index3 n = lattice();
  const int i = int(q % size_t(n[0]));
  const size_t rest = q / size_t(n[0]);
  return {i, int(rest % size_t(n[1])), int(rest / size_t(n[1]))};
}

bool DesignGrid::inside(const Index3& l) const {
  const Index3 n = lattice();
  return (l.array() >= 0).all() && (l.array() < n.array()).all();
}

Vec3 DesignGrid::position(size_t q) const {
  const Index3 l = lattice_coord(q);
  const Real s = spacing();
  return {(l[0] + 0.5) * s, (l[1] + 0.5) * s, planar ? 0.5 * cell_size : (l[2] + 0.5) * s};
}

Index3 DesignGrid::cell_of(size_t q) const {
  const Index3 l = lattice_coord(q);
  return {l[0] / per_cell, l[1] / per_cell, planar ? 0 : l[2] / per_cell};
}

Real DesignGrid::point_volume() const {
  const Real s = spacing();
  return planar ? s * s * thickness : s * s * s;
}

Real DesignGrid::domain_volume() const { return point_volume() * Real(point_count()); }

Vec3 DesignGrid::extent() const { return cell_size * cells.cast<Real>(); }

DesignGrid DesignGrid::refined(int factor) const {
  DesignGrid r = *this;
  r.cell_size = cell_size / factor;
  r.cells = cells * factor;
  if (planar) r.cells[2] = 1;
  return r;
}

}  // namespace latmpm::optimize
