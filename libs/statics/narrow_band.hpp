// The narrow band of paper C Sec. 3.4: the grid nodes that the stencils of the material
// points reach are the only unknowns of the static solve. For each point the band keeps
// the nodes of its stencil with the weight S_ip and gradient ∇S_ip at the point's
// reference position X_p, from the explicit solver's shape-function policies (libs/mpm),
// so F_p = I + Σ_i u_i ⊗ ∇S_ip (paper C Eq. 32) uses exactly the shape functions a dynamic
// run of the same scene uses.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "mpm/real.hpp"
#include "mpm/shape_function_kind.hpp"

namespace latmpm::statics {

using mpm::Real;
using mpm::Vec3;

struct NarrowBand {
  Real cell_size = 0;                  // h, m: nodes at x = (i, j, k)·h
  mpm::ShapeFunctionKind shape{};
  int nodes_per_axis = 0;              // of the shape function's stencil
  std::vector<Eigen::Vector3i> node;   // grid coordinates, sorted by (k, j, i)

  // Per point p the entries e in [point_offset[p], point_offset[p+1]): band node
  // entry_node[e] with weight entry_weight[e] and gradient entry_gradient[e] (1/m).
  // Nodes whose weight and gradient are both exactly zero are left out.
  std::vector<uint32_t> point_offset;
  std::vector<uint32_t> entry_node;
  std::vector<Real> entry_weight;
  std::vector<Vec3> entry_gradient;

  // Per node n the entries e in [node_entry_offset[n], node_entry_offset[n+1]) are
  // node_entry[...]: the point entries that reference the node, by increasing point.
  std::vector<uint32_t> node_entry_offset;
  std::vector<uint32_t> node_entry;
  std::vector<uint32_t> entry_point;  // the point of entry e

  size_t point_count() const { return point_offset.empty() ? 0 : point_offset.size() - 1; }
  size_t node_count() const { return node.size(); }
  Vec3 node_position(size_t n) const { return cell_size * node[n].cast<Real>(); }
  // Band index of grid node (i, j, k), or −1 when it is not in the band.
  long find(const Eigen::Vector3i& grid_coord) const;
};

// Builds the band of the points at reference positions X (m) with GIMP half-sizes
// `half_size` (m, used by uGIMP and cpGIMP; cpGIMP's domain in the reference
// configuration is its initial one). Throws InputError for DDMP, whose modified gradient
// is defined on the deforming grid, not on a reference configuration.
NarrowBand build_narrow_band(const std::vector<Vec3>& X, const std::vector<Vec3>& half_size,
                             Real cell_size, mpm::ShapeFunctionKind shape);

}  // namespace latmpm::statics
