// The compile-time flags of a shape-function policy (shape_*.hpp), with their defaults. Every
// policy inherits ShapeFlags and sets only the flags that differ; the step asks `Shape::flag`.
#pragma once

namespace latmpm::mpm {

struct ShapeFlags {
  static constexpr bool uses_half_size = false;     // the particle's domain half-size enters S (GIMP)
  static constexpr bool stretches_with_f = false;   // that domain follows F (CPGIMP)
  static constexpr bool trims_zero_planes = false;  // outer nodes often exactly zero: TrimmedStencils (stencil.hpp)
  static constexpr bool smoothed_gradient = false;  // DDMP: a smoothed gradient part (shape_ddmp.hpp)
  static constexpr bool smoothed_on_grid = false;   // DDMP: that part evaluated on the grid (DdmpGridShape)
  static constexpr bool per_node_gradient = false;  // DDMP: a gradient part per stencil node, `smoothed[N³]`
  static constexpr bool uses_domain_vertices = false;  // CPDI: the stencil from the particle's domain (shape_cpdi.hpp)
};

}  // namespace latmpm::mpm
