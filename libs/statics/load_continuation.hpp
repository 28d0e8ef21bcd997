// Equilibrium under dead point loads by adaptive load continuation: the projected Newton of
// projected_newton.hpp (paper C Algorithm 1) solves E(u) = Σ V_p ψ_p − λ f·u for load
// factors λ rising to 1, each from the previous λ's equilibrium. Paper C Sec. 4.3 solves
// its large-load neo-Hookean designs with projected Newton and the inversion-free line
// search and says no more; a soft (grey) design under a large load sits far from u = 0, so
// one Newton solve from rest may not reach it in a bounded number of steps.
//   1. From the start u (e.g. the previous design's equilibrium: a design iteration changes
//      the densities a little), the whole load at once.
//   2. Otherwise from rest: λ += Δλ from Δλ = first_step; a failed step is retried from the
//      last equilibrium with Δλ halved, down to 1/max_increments of the load; after a
//      converged step Δλ doubles again (up to what is left).
#pragma once
#include <string>
#include <vector>

#include "statics/projected_newton.hpp"

namespace latmpm::statics {

struct LoadContinuation {
  NewtonOptions newton;             // each step's projected Newton
  Real accepted = 0;                // a step that stops above newton.tolerance but at or below this relative residual counts as converged
  Real first_step = 0.25;           // Δλ of the first step from rest
  int max_increments = 256;         // smallest Δλ = 1 / max_increments
  bool try_start_first = true;      // step 1: the whole load from the given start
};

struct ContinuationReport {
  bool converged = false;
  bool from_start = false;          // the whole load from the start converged (step 1)
  int newton_iterations = 0;        // over every try, failed ones included
  int steps = 0;                    // converged load steps from rest (0: from the start)
  int failed_steps = 0;             // load steps retried with a smaller Δλ
  Real load_factor = 0;             // λ reached (1 when converged)
  NewtonReport last;                // the final Newton solve
  std::string failure;              // why it stopped without converging
};

// force: the full dead load on each point (N). u: the start on entry (it must not invert a
// point: det F_p > 0; an inverting start is skipped), the equilibrium under the whole load
// on return when converged (the last equilibrium otherwise). Leaves the problem's point
// forces at the whole load.
ContinuationReport solve_by_load_continuation(StaticProblem& problem, const Dirichlet& dirichlet,
                                              const std::vector<Vec3>& force, Vector& u, SparseSolver& solver,
                                              const LoadContinuation& settings = {});

}  // namespace latmpm::statics
