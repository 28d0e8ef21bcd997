// What a material model sees of a particle's motion over one step: never the particle.
#pragma once
#include "mpm/real.hpp"

namespace latmpm::mpm {

struct Deformation {
  const Mat3& velocity_gradient;  // L = Σ v_i ⊗ ∇S_i over the step, 1/s
  const Mat3& f_new;              // F at the end of the step, F_new = (I + dt L) F_old
  Real jacobian;                  // J = det F_new
  Real dt;                        // s
};

}  // namespace latmpm::mpm
