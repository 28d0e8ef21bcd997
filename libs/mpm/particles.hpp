// Particle state as a structure of arrays: one array per quantity, no per-particle
// objects. The solver keeps particles sorted by grid bucket for locality, so the index of a
// particle changes during a run; `id` is its index in the original PointSet.
//
// F and σ go one step further: one array per tensor component, so the eight particles of a
// constitutive group (transfer.hpp) load and store each component as one contiguous SIMD
// value instead of transposing 15 values per particle in and out of the lanes. Elsewhere
// they are read and written whole through deformation(p) / stress(p) and the setters.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "mpm/real.hpp"

namespace latmpm::mpm {

struct Particles {
  std::vector<Vec3> position;        // m
  std::vector<Vec3> velocity;        // m/s
  std::vector<Real> mass;            // kg (density × mass scaling × initial volume)
  std::vector<Real> volume0;         // m³, initial volume V0 (current volume = J · V0)
  // F, dimensionless: F(r, c) of particle p is deformation_component[3 r + c][p].
  std::array<std::vector<Real>, 9> deformation_component;
  // Cauchy stress, Pa: Voigt component c (xx yy zz yz xz xy) of particle p is
  // stress_component[c][p].
  std::array<std::vector<Real>, 6> stress_component;
  std::vector<Vec3> half_size0;      // m, initial GIMP particle-domain half-lengths (a point
                                     // set's zero half-size becomes cell_size / (2 ppc))
  std::vector<int32_t> body;         // index into Simulation::bodies()
  std::vector<uint32_t> id;          // index in the PointSet the particles came from
  std::vector<uint8_t> flags;        // bit flags below

  static constexpr uint8_t record_flag = 1;  // carries the record tag
  static constexpr uint8_t held_flag = 2;    // deformable point whose stencil nodes are held at rest

  size_t size() const { return position.size(); }

  Real deformation(size_t p, int r, int c) const { return deformation_component[size_t(3 * r + c)][p]; }
  Mat3 deformation(size_t p) const {
    Mat3 F;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) F(r, c) = deformation(p, r, c);
    return F;
  }
  void set_deformation(size_t p, const Mat3& F) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) deformation_component[size_t(3 * r + c)][p] = F(r, c);
  }
  SymTensor stress(size_t p) const {
    SymTensor s;
    for (int c = 0; c < 6; ++c) s[c] = stress_component[size_t(c)][p];
    return s;
  }
  void set_stress(size_t p, const SymTensor& s) {
    for (int c = 0; c < 6; ++c) stress_component[size_t(c)][p] = s[c];
  }

  Real jacobian(size_t p) const { return deformation(p).determinant(); }
  Real von_mises_stress(size_t p) const { return von_mises(stress(p)); }
  // Applies the same permutation (new index i takes old index order[i]) to every array.
  void permute(const std::vector<uint32_t>& order);
  void resize(size_t n);
  // Bytes held by the arrays (their capacity).
  size_t memory_bytes() const;
};

}  // namespace latmpm::mpm
