// Material points for the static-solver tests, built directly: a box of points on the
// voxelizer's lattice, x = (i + (k + ½)/ppc)·h, each with volume (h/ppc)³ and GIMP
// half-size h/(2 ppc), and the StaticProblem over them.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "mpm/material.hpp"
#include "statics/displacement_control.hpp"
#include "statics/static_problem.hpp"

namespace latmpm::statics::test {

struct PointBlock {
  std::vector<Vec3> position, half_size;
  std::vector<Real> volume;
};

// Points filling the cell-aligned box [lo, hi) (m).
inline PointBlock point_block(const Vec3& lo, const Vec3& hi, Real h, int ppc) {
  PointBlock b;
  const Real s = h / ppc;
  const Eigen::Vector3i n = ((hi - lo) / s).array().round().cast<int>();
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        b.position.push_back(lo + s * Vec3(i + 0.5, j + 0.5, k + 0.5));
        b.half_size.push_back(Vec3::Constant(s / 2));
        b.volume.push_back(s * s * s);
      }
  return b;
}

inline mpm::MaterialParameters material(mpm::MaterialKind kind, Real young, Real poisson) {
  mpm::MaterialParameters m;
  m.kind = kind;
  m.young_modulus = young;
  m.poisson_ratio = poisson;
  m.density = 1000;
  return m;
}

inline StaticProblem make_problem(const PointBlock& b, Real h, mpm::ShapeFunctionKind shape,
                                  const mpm::MaterialParameters& m) {
  return StaticProblem(build_narrow_band(b.position, b.half_size, h, shape), b.volume,
                       std::vector<uint16_t>(b.position.size(), 0), {ElasticEnergy::from(m)});
}

// A neo-Hookean cube of 4 cells (h = 1 mm, E = 10 MPa, ν = 0.3) on quadratic B-splines, 2
// points per cell per direction: the block two statics tests compress between clamped platens.
inline StaticProblem neo_hookean_cube(Real h) {
  const PointBlock block = point_block(Vec3::Zero(), Vec3::Constant(4 * h), h, 2);
  return make_problem(block, h, mpm::ShapeFunctionKind::bspline2, material(mpm::MaterialKind::neo_hookean, 1e7, 0.3));
}

// Clamped platens on a block standing on z = 0: the nodes at grid layer k <= 0 are held, those
// at k >= top_layer move with the platen (travel and increments are the caller's).
inline PlatenLoading clamped_platens(const StaticProblem& problem, int top_layer) {
  PlatenLoading loading;
  for (size_t n = 0; n < problem.band().node_count(); ++n) {
    const int k = problem.band().node[n][2];
    if (k <= 0) loading.support_nodes.push_back(n);
    if (k >= top_layer) loading.platen_nodes.push_back(n);
  }
  return loading;
}

// The clamped platens moving the top down by `travel` in `increments` equal steps.
inline PlatenLoading clamped_platens(const StaticProblem& problem, int top_layer, Real travel, int increments) {
  PlatenLoading loading = clamped_platens(problem, top_layer);
  loading.travel = travel;
  loading.increments = increments;
  return loading;
}

}  // namespace latmpm::statics::test
