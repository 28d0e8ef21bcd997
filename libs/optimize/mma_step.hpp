// One iteration of the method of moving asymptotes (Svanberg 1987, paper C Sec. 4.1) taken
// with NLopt's MMA (NLOPT_LD_MMA): the caller has evaluated the objective and one
// inequality constraint g ≤ 0 with their gradients at x; NLopt builds the convex separable
// MMA approximation around x inside the move-limited box [max(lb, x − move), min(ub, x + move)]
// (paper C's step-length control through the box constraints), solves its dual, and the
// first trial point it proposes is the next design. NLopt is stopped there (nlopt_force_stop)
// before it asks for a second evaluation, so each design iteration costs one static solve.
// Following paper C Sec. 4.1 (2), the objective and constraint are scaled so that their
// gradients have unit 2-norm.
#pragma once
#include <vector>

#include "mpm/real.hpp"

namespace latmpm::optimize {

using mpm::Real;

struct MmaInput {
  std::vector<Real> x;                 // current design
  Real objective = 0;                  // f(x)
  std::vector<Real> objective_gradient;
  Real constraint = 0;                 // g(x), feasible where ≤ 0
  std::vector<Real> constraint_gradient;
  std::vector<Real> lower, upper;      // global bounds
  std::vector<Real> move;              // largest change of each variable in one iteration
};

// The next design. Throws NumericalError when NLopt fails before proposing a point.
std::vector<Real> mma_step(const MmaInput& in);

}  // namespace latmpm::optimize
