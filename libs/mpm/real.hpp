// The floating-point types of the solver and the small fixed-size types built on them.
// Everything in libs/mpm computes in `Real` (double). `ParticleReal` is the type of the
// particle state that is not a sum over many steps or points: velocity, F, stress, mass,
// initial volume and half-size (particles.hpp). It is double unless the build chose the
// mixed-precision mode (CMake LATMPM_PRECISION=mixed, docs/solver.md "Precision"); then it
// is float, and positions, the grid's sums and the energies stay double.
#pragma once
#include <Eigen/Core>
#include <Eigen/LU>  // determinant()
#include <cmath>

namespace latmpm::mpm {

using Real = double;
using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;

// A symmetric tensor (Cauchy stress) in Voigt order xx, yy, zz, yz, xz, xy.
using SymTensor = Eigen::Matrix<Real, 6, 1>;

#if defined(LATMPM_MIXED_PRECISION)
using ParticleReal = float;
inline constexpr const char* precision_name = "mixed";
#else
using ParticleReal = Real;
inline constexpr const char* precision_name = "double";
#endif
using ParticleVec3 = Eigen::Matrix<ParticleReal, 3, 1>;
using ParticleMat3 = Eigen::Matrix<ParticleReal, 3, 3>;
using ParticleSymTensor = Eigen::Matrix<ParticleReal, 6, 1>;

template <class Scalar>
inline Eigen::Matrix<Scalar, 3, 3> to_matrix(const Eigen::Matrix<Scalar, 6, 1>& s) {
  Eigen::Matrix<Scalar, 3, 3> m;
  m << s[0], s[5], s[4],
       s[5], s[1], s[3],
       s[4], s[3], s[2];
  return m;
}

inline SymTensor to_voigt(const Mat3& m) {
  SymTensor s;
  s << m(0, 0), m(1, 1), m(2, 2), Real(0.5) * (m(1, 2) + m(2, 1)),
      Real(0.5) * (m(0, 2) + m(2, 0)), Real(0.5) * (m(0, 1) + m(1, 0));
  return s;
}

// von Mises equivalent stress sqrt(3/2 s:s), s the deviator (Pa).
template <class Scalar>
inline Real von_mises(const Eigen::Matrix<Scalar, 6, 1>& s) {
  const Real p = (s[0] + s[1] + s[2]) / 3;
  const Real dx = s[0] - p, dy = s[1] - p, dz = s[2] - p;
  const Real j2 = Real(0.5) * (dx * dx + dy * dy + dz * dz) + s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
  return std::sqrt(3 * j2);
}

}  // namespace latmpm::mpm
