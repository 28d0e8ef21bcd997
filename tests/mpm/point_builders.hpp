// Point sets for the solver tests, built directly (no voxelizer): regular lattices of
// points placed like the voxelizer's, x = (i + (k + ½)/ppc)·h, with GIMP half-sizes h/(2 ppc).
#pragma once
#include <functional>
#include <string>

#include "mpm/body.hpp"
#include "mpm/j2_plasticity.hpp"
#include "mpm/real.hpp"
#include "mpm/settings.hpp"
#include "points/point_set.hpp"

namespace latmpm::mpm::test {

inline PointSet empty_point_set(double h, int ppc) {
  PointSet ps;
  ps.cell_size = h;
  ps.ppc = ppc;
  return ps;
}

inline int add_body_name(PointSet& ps, const std::string& body) {
  int b = ps.body_index(body);
  if (b < 0) {
    ps.body_names.push_back(body);
    b = int(ps.body_names.size()) - 1;
  }
  return b;
}

// Adds the lattice points inside [lo, hi) (cell-aligned box, m) that satisfy `inside`.
inline void add_points(PointSet& ps, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                       const std::string& body,
                       const std::function<bool(const Eigen::Vector3d&)>& inside = nullptr) {
  const int b = add_body_name(ps, body);
  const double s = ps.cell_size / ps.ppc;
  const Eigen::Vector3i n = ((hi - lo) / s).array().round().cast<int>();
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        const Eigen::Vector3d x = lo + s * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5);
        if (inside && !inside(x)) continue;
        ps.position.push_back(x);
        ps.volume.push_back(s * s * s);
        ps.body.push_back(b);
        ps.half_size.push_back(Eigen::Vector3d::Constant(s / 2));
        for (auto& [name, mask] : ps.tags) mask.push_back(0);
      }
}

inline void tag_points(PointSet& ps, const std::string& tag,
                       const std::function<bool(size_t)>& select) {
  auto& mask = ps.tags[tag];
  mask.assign(ps.size(), 0);
  for (size_t p = 0; p < ps.size(); ++p) mask[p] = select(p) ? 1 : 0;
}

// The update scheme a test runs a shape function with: USL, the papers' scheme, for every
// shape (DDMP hands its small-mass nodes on to their neighbours, ddmp_grid.hpp).
inline UpdateScheme scheme_for(ShapeFunctionKind) { return UpdateScheme::usl; }

inline MaterialParameters elastic(double young, double poisson, double density,
                                  MaterialKind kind = MaterialKind::linear_elastic) {
  MaterialParameters m;
  m.kind = kind;
  m.young_modulus = young;
  m.poisson_ratio = poisson;
  m.density = density;
  return m;
}

// Paper B's J2 law (j2_plasticity.hpp) as a body's material.
inline MaterialParameters j2_material(const J2Parameters& j2, double density) {
  MaterialParameters m = elastic(j2.young_modulus, j2.poisson_ratio, density, MaterialKind::j2);
  m.initial_yield = j2.initial_yield, m.saturation_yield = j2.saturation_yield;
  m.saturation_rate = j2.saturation_rate, m.linear_hardening = j2.linear_hardening;
  return m;
}

inline BodySettings deformable(const std::string& name, const MaterialParameters& m) {
  BodySettings b;
  b.name = name;
  b.material = m;
  return b;
}

inline BodySettings rigid(const std::string& name, BodyRole role, const Vec3& velocity, double density) {
  BodySettings b;
  b.name = name;
  b.role = role;
  b.velocity = velocity;
  b.material.density = density;
  return b;
}

}  // namespace latmpm::mpm::test
