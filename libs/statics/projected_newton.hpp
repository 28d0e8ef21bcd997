// Projected Newton with an inversion-free backtracking line search (paper C Algorithm 1,
// Sec. 3.3): minimises E(u) of a StaticProblem under Dirichlet conditions.
//   1. g = ∇E(u); stop when the free part ‖g_F‖ ≤ tolerance · max(‖f_int‖, ‖f‖).
//   2. H = Σ_p Bᵀ Π(V_p ∂P/∂F) B with Π the semidefinite projection (spd_projection.hpp);
//      rows and columns of prescribed unknowns replaced by the identity (scaled). The true
//      Hessian is used instead wherever it is positive definite and gives a descent direction.
//   3. Solve H d = −g (d = remaining prescribed motion on the constrained unknowns).
//   4. α₀ = min(1, inversion-free bound) for neo-Hookean energies; halve α until
//      det F_p(u + αd) > 0 for all points (checked before any energy is evaluated) and
//      E(u + αd) ≤ E(u) + c α gᵀd (Armijo).
// While prescribed unknowns still move (the first iteration of a load increment), the step
// raises the energy by design: it is bounded by the inversion-free step only.
// Linear elasticity is quadratic: one iteration reaches the solution.
#pragma once
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "statics/dirichlet.hpp"
#include "statics/sparse_solver.hpp"
#include "statics/static_problem.hpp"

namespace latmpm::statics {

// One Newton step, as NewtonOptions::on_step is told of it.
struct NewtonStep {
  int iteration = 0;           // 1, 2, ... within the solve
  Real residual_before = 0;    // relative residual force at the step's start
  Real alpha = 0;              // step length taken
  bool true_tangent = false;   // the unprojected Hessian gave the direction
  bool krylov = false;         // solved by CG on an earlier factor (else factorised)
  int linear_iterations = 0;   // of this step's solve
};

struct NewtonOptions {
  Real tolerance = 1e-8;         // relative residual force at which the solve stops
  int max_iterations = 50;
  Real armijo = 1e-4;            // sufficient-decrease constant c
  Real inversion_margin = 0.1;   // ε of the step bound: det F may shrink at most to ε det F per step
  int max_halvings = 40;         // backtracking steps before the line search gives up
  // Diagonal shift (× mean diagonal) added to the projected Hessian: the point quadrature
  // leaves zero-energy modes where a part is two cells thick (quadratic B-splines, 2 points
  // per cell: 5 nodes, 4 sample planes per axis). ×1000 while the factorisation fails.
  Real shift = 1e-12;
  // Below this relative residual the true Hessian is tried first: where it is positive
  // definite the step is a full Newton step (the per-point projection, active wherever a
  // point's tangent is indefinite, e.g. in compression, makes convergence linear: on the
  // QUICK T1P20 path at 3 mm, 25 projected steps from 5e-3 to 1e-3, then 3 true-tangent
  // steps to 1e-10). Default: from the first step that does not move the platen.
  Real true_tangent_below = std::numeric_limits<Real>::infinity();
  // Where the true Hessian was indefinite, it is tried again once the residual has fallen
  // by this factor (0: never again in this solve).
  Real retry_true_tangent_after = 0.1;
  // Krylov steps (modified Newton with Krylov acceleration): where a direct solver holds a
  // factor of an earlier positive definite matrix (an earlier Newton step's, or the last
  // increment's stability check), each step's system is first solved by CG preconditioned
  // with that factor, at most this many iterations, to the forcing tolerance
  // min(krylov_forcing, 0.1 × relative residual) (Eisenstat–Walker-like: superlinear
  // convergence); only where that fails is the matrix factorised. 0: every step factorises.
  int krylov_iterations = 0;
  Real krylov_forcing = 1e-2;
  // Stop on slow convergence: where the last `stall_window` steps were all projected (the
  // true tangent indefinite or not tried) and each cut the residual by a factor in
  // [stall_ratio, 1), convergence is linear, and where at that rate (their geometric mean)
  // the tolerance lies beyond max_iterations the solve fails now instead of at the budget.
  // Near a lattice's instability such a solve creeps towards a buckled state at 0.7–0.95 a
  // step and never converges (docs/statics.md): each failed attempt there cost the whole
  // budget, ~20 steps of ~25 s. Alternating true-tangent/projected steps, whose residual
  // rises and falls, do not qualify (the slow increments that converge on those paths are of
  // that kind). Before the rule fails a solve that is skipping an indefinite true tangent,
  // the true tangent is tried once more (and the window starts again). A second rule stops a
  // solve whose residual has not set a new best for 2 × stall_window steps
  // (no_progress_stall). Both can stop a solve that would still have converged within its
  // budget: the linear rule extrapolates the rate to the tolerance, not to the next scheduled
  // retry of the true tangent (retry_true_tangent_after), which may converge quadratically;
  // the other stops a residual that rises for 2 × stall_window steps before it falls. The
  // displacement control then halves the step (docs/statics.md). 0 (the library default:
  // load continuation and the optimiser's compliance solves run to their budget): never stop
  // early. The static run's default is 4 (StaticSettings::stall_window).
  int stall_window = 0;
  Real stall_ratio = 0.6;
  // Asked before each step: true stops the solve unconverged (NewtonReport::stopped), as a
  // signal stops a run between steps (core/interruption.hpp). Empty: never.
  std::function<bool()> stop_requested;
  // Told after each step: on a paper-size lattice one Newton step is ~10 s and an increment
  // that does not converge takes tens of minutes, so the run logs every step.
  std::function<void(const NewtonStep&)> on_step;
  // Told where a solve ends unconverged (not where a stop request ended it), with why; the
  // caller may solve the same increment again (from the last equilibrium, or factorising
  // only), halve the step, or end the path, so a failure in the log may be followed by a
  // converged increment.
  std::function<void(const std::string&)> on_failure;
};

struct NewtonReport {
  bool converged = false;
  int iterations = 0;             // Newton steps taken (linear solves)
  std::vector<Real> residual;     // relative residual ‖g_F‖/scale before each step and at the end
  std::vector<Real> energy;       // E(u) at the same points, J
  std::vector<Real> step;         // α of each step
  int true_tangent_steps = 0;     // steps taken with the unprojected Hessian
  bool last_step_true_tangent = false;  // the last step's Hessian was the true one, factorised
                                        // (a direct solver: positive definite)
  int linear_iterations = 0;      // summed over the steps (CG, AMG; 1 per direct solve)
  int krylov_steps = 0;           // steps solved by CG preconditioned with an earlier factor
  Real linear_residual = 0;       // relative residual of the last linear solve
  Real min_jacobian = 1;          // smallest det F_p at the end
  std::string failure;            // why it stopped without converging
  bool stopped = false;           // stop_requested() ended it (not a failure of the method)
};

// The stall rule of NewtonOptions::stall_window, applied before each step: empty where the
// solve may go on, else why it stops. residual[i] is the relative residual before step i + 1
// (the last entry the current one); projected_at_rest[i] says whether step i + 1 was a
// projected step with the prescribed unknowns already in place.
std::string linear_convergence_stall(const std::vector<Real>& residual, const std::vector<char>& projected_at_rest,
                                     const NewtonOptions& options);

// The second stall rule: empty where the solve may go on; else, where the relative residual
// has not gone below its best since first_at_rest (the first residual with the prescribed
// unknowns in place) for 2 × stall_window steps, why it stops. Converging solves whose
// true-tangent and projected steps alternate set a new best every 2–3 steps (paper-size T2P40,
// docs/statics.md); a true-tangent solve that bounces near a bifurcation does not.
std::string no_progress_stall(const std::vector<Real>& residual, size_t first_at_rest, const NewtonOptions& options);

// u: the start on entry (prescribed unknowns may differ from their values), the result on
// return. Never evaluates the energy of an F with det F ≤ 0.
NewtonReport solve_equilibrium(StaticProblem& problem, const Dirichlet& dirichlet, Vector& u,
                               SparseSolver& solver, const NewtonOptions& options = {});

}  // namespace latmpm::statics
