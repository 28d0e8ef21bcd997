// The static solver's settings as a scene gives them ([solver] kind = "static", docs/scene.md):
// one struct with its defaults, read by scene/solver_readers.cpp and taken by the static run
// (libs/static_run) as it is. A new setting is a field here and its key in that reader.
#pragma once
#include <string>
#include <vector>

#include "mpm/real.hpp"

namespace latmpm::statics {

using mpm::Real;

enum class LinearSolverKind { ldlt, cg, cholmod, amg, automatic };

// "ldlt", "cg", "cholmod", "amg", "auto" (sparse_solver.cpp: the one table).
std::string to_string(LinearSolverKind kind);
std::vector<std::string> linear_solver_names();
// Throws InputError(where, field, ...) for an unknown name.
LinearSolverKind parse_linear_solver(const std::string& name, const std::string& where = "",
                                     const std::string& field = "");

struct StaticSettings {
  int increments = 20;  // equilibrium steps to the end travel (displacement_control.hpp)
  LinearSolverKind linear_solver = LinearSolverKind::automatic;  // auto: CHOLMOD unless its factor is too big (sparse_solver.hpp)
  Real tolerance = 1e-8;  // relative residual force of each increment (NewtonOptions)
  bool check_stability = true;  // end the path at the first unstable equilibrium
  bool predictor = true;  // start each increment from the secant extrapolation of the last two (displacement_control.hpp)
  // Adaptive increments: the step may grow to this multiple of travel / increments while
  // Newton converges fast (1: fixed increments; displacement_control.hpp). A grown step can
  // step over a shallow load maximum (docs/statics.md), so 1 stays the default.
  Real max_increment_growth = 1;
  // Krylov steps: CG preconditioned by the last factor, at most this many iterations, before
  // a Newton step refactorises (NewtonOptions::krylov_iterations; 0: every step factorises).
  // 20: on the paper-size lattice a CG iteration costs ~1/30 of a factorisation (docs/statics.md).
  int krylov_iterations = 20;
  Real stabilisation = 0.1;  // β of the affine stabilisation, × shear modulus (affine_stabilisation.hpp)
  // Newton steps before an increment counts as not converged, and halvings of the step
  // after a Newton failure (and of an indefinite tangent's bracket) before the path ends
  // (NewtonOptions::max_iterations, PlatenLoading::bisections). On a paper-size lattice a
  // Newton step is 10-25 s of CPU: a failed step costs one solve of this many steps, the
  // smallest step up to three (docs/statics.md).
  int newton_iterations = 50;
  int bisections = 6;
  // Projected steps of steady linear convergence after which a Newton solve that cannot reach
  // the tolerance within newton_iterations at that rate counts as failed at once (after one
  // more true-tangent try), and half the steps a solve may go without a new best residual
  // (NewtonOptions::stall_window; 0: a solve fails only at its budget).
  int stall_window = 4;
};

}  // namespace latmpm::statics
