// What a material model sees of a particle's motion over one step: never the particle.
// T is Real for one particle or Pack for eight particles updated together (one lane each);
// models write their formulas once, as templates over T.
#pragma once
#include "mpm/real.hpp"
#include "mpm/simd.hpp"

namespace latmpm::mpm {

template <class T>
struct Deformation {
  T velocity_gradient[3][3];  // L_ab = ∂v_a/∂x_b over the step, 1/s
  T f_new[3][3];              // F at the end of the step, F_new = (I + dt L) F_old
  T jacobian;                 // J = det F_new
  T jacobian_old;             // det F_old, J at the start of the step (energy of rate models)
  Real dt;                    // s
};

// det F, written out once for the gather kernel (T = Pack) and the observers that read J
// back from the stored F in the same lane order (observers.cpp): the same expression gives
// the same bits.
template <class T>
inline T determinant(const T (&F)[3][3]) {
  return F[0][0] * (F[1][1] * F[2][2] - F[1][2] * F[2][1]) - F[0][1] * (F[1][0] * F[2][2] - F[1][2] * F[2][0]) +
         F[0][2] * (F[1][0] * F[2][1] - F[1][1] * F[2][0]);
}

// Cauchy stress in Voigt order xx yy zz yz xz xy, Pa.
template <class T>
using Stress = T[6];

// For one particle from Eigen types (set-up, tests): F is F_new = (I + dt L) F_old.
inline Deformation<Real> make_deformation(const Mat3& L, const Mat3& F, Real dt) {
  Deformation<Real> d;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) d.velocity_gradient[a][b] = L(a, b), d.f_new[a][b] = F(a, b);
  d.jacobian = F.determinant();
  d.jacobian_old = d.jacobian / (Mat3::Identity() + dt * L).determinant();
  d.dt = dt;
  return d;
}

}  // namespace latmpm::mpm
