// Tiling rule of the tetrahedral lattice (REFERENCE.md "Tetrahedral lattice", Decision).
//
// In the horizontal plane take the lattice vectors a1 = (a, 0), a2 = (a/2, a√3/2) and the
// three foot vectors f0 = (a/2, a/(2√3)), f1 = f0 − a1, f2 = f0 − a2 (length d = a/√3, 120°
// apart, f0 + f1 + f2 = 0). A tripod at node n has its feet at n + f_k, L sin φ lower.
// Because f_k − f0 is a lattice vector, all feet of a layer lie on the one translated lattice
// {nodes} + f0, each foot shared by up to three tripods of that layer.
// Layer i's nodes form the lattice shifted by −i·f0: then the feet of layer i+1 lie at
// {nodes_i − f0} + f0 = {nodes_i}, exactly above layer i's nodes, i.e. on the tops of its
// vertical struts (height 2L/3 above its nodes). Since 3·f0 = a1 + a2, the shift repeats
// every three layers: ABC stacking.
#include "geometry/tetrahedral_lattice.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "geometry/strut_graph_builder.hpp"

namespace latmpm {

double TetrahedralLattice::foot_distance() const { return strut_length * std::cos(angle); }
double TetrahedralLattice::node_spacing() const { return std::sqrt(3.0) * foot_distance(); }
double TetrahedralLattice::layer_height() const {
  return strut_length * std::sin(angle) + 2.0 * strut_length / 3.0;
}

namespace {

// The `count` integers m for which |offset + m·spacing| is smallest (ties go to the larger
// coordinate, so even counts and half-spacing offsets give one deterministic choice).
std::vector<long> nearest_indices(double offset, double spacing, int count) {
  const long centre = std::lround(-offset / spacing);
  std::vector<long> candidates;
  for (long m = centre - count - 1; m <= centre + count + 1; ++m) candidates.push_back(m);
  auto key = [&](long m) {
    const double x = offset + m * spacing;
    return std::make_pair(std::round(std::abs(x) / spacing * 1e9), -x);  // rounding: ties exact
  };
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](long p, long q) { return key(p) < key(q); });
  candidates.resize(count);
  return candidates;
}

// Node positions (x, y) of one layer whose lattice is shifted by `offset`.
std::vector<Eigen::Vector2d> layer_nodes(const TetrahedralLattice& s, const Eigen::Vector2d& offset) {
  const double a = s.node_spacing(), row_spacing = a * std::sqrt(3.0) / 2.0;
  const Eigen::Vector2d a1(a, 0), a2(a / 2, row_spacing);
  std::vector<Eigen::Vector2d> nodes;
  if (s.footprint == Footprint::brick) {
    // Rows are lines of constant m (node = offset + n·a1 + m·a2).
    for (long m : nearest_indices(offset.y(), row_spacing, s.rows)) {
      const double row_x = offset.x() + m * a2.x();
      for (long n : nearest_indices(row_x, a, s.nodes_per_row))
        nodes.emplace_back(row_x + n * a, offset.y() + m * row_spacing);
    }
  } else {
    // Parallelogram n0..n0+nx−1, m0..m0+ny−1 with centroid nearest the origin: solve for the
    // real-valued corner, then try the integer corners around it.
    const Eigen::Vector2d half_extent = 0.5 * ((s.nodes_per_row - 1) * a1 + (s.rows - 1) * a2);
    Eigen::Matrix2d basis;
    basis << a1, a2;
    const Eigen::Vector2d ideal = basis.inverse() * (-offset - half_extent);
    double best = INFINITY;
    long best_n = 0, best_m = 0;
    for (long n = std::lround(std::floor(ideal.x())); n <= std::lround(std::ceil(ideal.x())); ++n)
      for (long m = std::lround(std::floor(ideal.y())); m <= std::lround(std::ceil(ideal.y())); ++m) {
        const double distance = (offset + n * a1 + m * a2 + half_extent).norm();
        if (distance < best - 1e-9 * a) best = distance, best_n = n, best_m = m;
      }
    for (long m = best_m; m < best_m + s.rows; ++m)
      for (long n = best_n; n < best_n + s.nodes_per_row; ++n)
        nodes.push_back(offset + n * a1 + m * a2);
  }
  return nodes;
}

}  // namespace

StrutGraph build_tetrahedral_lattice(const TetrahedralLattice& s) {
  if (!(s.strut_length > 0) || !(s.strut_diameter > 0) || !(s.angle > 0) ||
      !(s.angle < M_PI / 2) || s.nodes_per_row < 1 || s.rows < 1 || s.layers < 1)
    throw std::invalid_argument("tetrahedral lattice: sizes out of range");
  const double L = s.strut_length, a = s.node_spacing(), h = s.layer_height();
  const double rise = L * std::sin(s.angle), vertical = 2.0 * L / 3.0;
  const double sign = s.stacking == Stacking::abc ? 1.0 : -1.0;  // ACB: mirrored tripods
  const Eigen::Vector2d f0 = sign * Eigen::Vector2d(a / 2, a / (2 * std::sqrt(3.0)));
  const Eigen::Vector2d feet[3] = {f0, f0 - Eigen::Vector2d(a, 0),
                                   f0 - Eigen::Vector2d(a / 2, a * std::sqrt(3.0) / 2)};
  // Mirroring flips f0 but not the lattice vectors: f_k = f0 − (lattice vector) still holds
  // with a1, a2 negated, which span the same lattice.
  const Eigen::Vector2d mirrored[3] = {f0, f0 + Eigen::Vector2d(a, 0),
                                       f0 + Eigen::Vector2d(a / 2, a * std::sqrt(3.0) / 2)};
  const Eigen::Vector2d* foot = s.stacking == Stacking::abc ? feet : mirrored;

  StrutGraphBuilder builder(1e-6 * L);
  const double radius = s.strut_diameter / 2;
  for (int layer = 0; layer < s.layers; ++layer) {
    const double z_feet = layer * h, z_node = z_feet + rise;
    for (const Eigen::Vector2d& n : layer_nodes(s, -double(layer) * f0)) {
      const Eigen::Vector3d node(n.x(), n.y(), z_node);
      for (int k = 0; k < 3; ++k)
        builder.strut(Eigen::Vector3d(n.x() + foot[k].x(), n.y() + foot[k].y(), z_feet), node, radius);
      builder.strut(node, node + Eigen::Vector3d(0, 0, vertical), radius);
    }
  }
  StrutGraph graph;
  builder.move_into(graph);
  return graph;
}

}  // namespace latmpm
