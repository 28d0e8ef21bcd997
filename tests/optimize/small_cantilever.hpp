// A small planar cantilever for the optimiser's tests: 8×4 cells of 1 mm, 2×2 points per
// cell, a 1 mm slab, clamped at x = 0, 1 N down on the points of the bottom-right cell.
#pragma once
#include "optimize/compliance.hpp"
#include "optimize/design_grid.hpp"
#include "optimize/load_case.hpp"

namespace latmpm::optimize::test {

inline DesignGrid small_grid(bool planar = true) {
  DesignGrid g;
  g.cell_size = 1e-3;
  g.cells = planar ? Index3(8, 4, 1) : Index3(6, 4, 4);
  g.per_cell = 2;
  g.planar = planar;
  g.thickness = planar ? 1e-3 : 0;
  return g;
}

inline LoadCase small_load_case(const DesignGrid& g) {
  LoadCase lc;
  Support clamp;
  clamp.box = {Vec3(-1, -1, -1), Vec3(1e-9, 1, 1)};
  clamp.name = "clamp";
  lc.supports.push_back(clamp);
  const Vec3 e = g.extent();
  Load tip;
  tip.box = {Vec3(e[0] - g.cell_size, -1, -1), Vec3(1, g.cell_size, 1)};
  tip.force = Vec3(0, -1, 0);
  tip.name = "tip";
  lc.loads.push_back(tip);
  return lc;
}

inline SimpMaterial small_material(Real weak_ratio = 1e-9) {
  SimpMaterial m;
  m.young_modulus = 1e9;
  m.poisson_ratio = 0.3;
  m.penalty = 3;
  m.weak_ratio = weak_ratio;
  return m;
}

}  // namespace latmpm::optimize::test
