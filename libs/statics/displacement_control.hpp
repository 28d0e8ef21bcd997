// Displacement-controlled loading (the static counterpart of the explicit solver's driven
// plate): a rigid platen moves in increments along `direction`; the band nodes it reaches
// take its displacement (all three components: no slip, like the explicit grid update),
// the supports' nodes stay at zero, and each increment is solved by projected Newton to the
// residual tolerance from the previous equilibrium. After each increment the true
// (unprojected) tangent is factorised: the static path ends at the first increment where it
// is not positive definite (a bifurcation or limit point: buckling), where the load falls
// (past a limit point; the only check where the true tangent is unusable, docs/statics.md)
// or where Newton fails at the smallest step. An indefinite tangent's travel is bracketed by
// bisection, a load maximum located by the parabola through the last three loads; a Newton
// failure halves the step and tries again from the last equilibrium, down to the increment
// over 2^bisections, so that the path ends only where no short step converges. The check factorises with the Newton solver
// itself when that is direct (one analysis, one factor in memory: the next Newton step
// refactorises anyway), else with its own CHOLMOD; where Newton's last step was a
// true-tangent step of a direct solver taken at a relative residual ≤ 1e-4, that
// factorisation (positive definite) answers the check: the state moved less since than the
// smallest eigenvalue of the tangent changes over an increment.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "statics/projected_newton.hpp"

namespace latmpm::statics {

struct PlatenLoading {
  std::vector<size_t> support_nodes;  // held at zero displacement
  std::vector<size_t> platen_nodes;   // moved with the platen
  Vec3 direction = -Vec3::UnitZ();    // unit vector of the platen's motion
  Real travel = 0;                    // m, total platen travel
  int increments = 10;
  bool check_stability = true;        // factorise the true tangent after each increment
  bool end_at_load_maximum = true;    // a falling load also ends the path (a limit point)
  int bisections = 6;                 // halvings of the indefinite tangent's bracket, and of the
                                      // step after a Newton failure before the path ends
  // Start each increment's Newton from the secant extrapolation of the last two equilibria
  // (from the last one where that inverts a point or does not converge).
  bool predictor = true;
  // Adaptive increments: the step starts at travel / increments and grows by `step_growth`
  // after each increment whose Newton took at most `fast_newton` steps, up to
  // max_step_growth × that, and shrinks by it after one that took more than twice that
  // (1: fixed increments). After a Newton failure's halvings the step grows back the same way.
  Real max_step_growth = 1;
  Real step_growth = 2;
  int fast_newton = 4;
};

struct PathPoint {
  Real travel = 0;          // m
  Real load = 0;            // N: force the platen exerts along its motion
  Real support_load = 0;    // N: force the supports exert against it
  Real energy = 0;          // J: stored elastic energy
  int newton_iterations = 0;  // including any spent from an abandoned prediction
  bool predicted = false;     // converged from the predictor's start
  int true_tangent_steps = 0; // of the converged solve: steps with the unprojected Hessian
  int linear_iterations = 0;
  int krylov_steps = 0;       // steps solved by CG preconditioned with an earlier factor
  Real linear_residual = 0;  // ‖K d − r‖ / ‖r‖ of the last linear solve
  Real residual = 0;        // final relative residual
  Real min_jacobian = 1;
  bool stable = true;       // true tangent positive definite (or not checked)
};

struct PathReport {
  std::vector<PathPoint> points;  // the converged increments, in order (bisection included)
  bool ended = false;             // an instability or a failure ended the path before `travel`
  std::string end_reason;         // "tangent not positive definite", "load maximum", "stopped"
                                  // (NewtonOptions::stop_requested), or Newton's failure
  bool stopped = false;           // a stop request ended it: end_travel is the last stable travel
  Real end_travel = 0;            // m: middle of the final bracket (last stable, first unstable
                                  // or failed at the smallest step);
                                  // a load maximum: the vertex of the parabola through the last
                                  // three loads (no bisection: the top is flat)
  Real end_load = 0;              // N: the load there (interpolated), or the last stable load
  int cut_backs = 0;              // steps halved after a Newton failure
  int checks_from_newton = 0;     // stability checks answered by Newton's last factorisation
  Real last_stable_travel = 0;    // m: the last travel found stable
  Real last_stable_load = 0;      // N: the load there
  PhaseTime stability_check;      // true-tangent assemblies and factorisations after increments
};

// Called after each converged increment with its point and displacement field.
using IncrementObserver = std::function<void(const PathPoint&, const Vector&)>;

// The vertex of the parabola through three (travel, load) points, t0 < t1 < t2 with
// F1 ≥ F0 and F1 > F2 (so it is concave and its vertex lies in [t0, t2]): {travel, load}.
// Where the path ends at a load maximum, the peak (no bisection: on a flat top every
// bisection load may fall).
std::pair<Real, Real> parabola_vertex(Real t0, Real f0, Real t1, Real f1, Real t2, Real f2);

PathReport load_by_platen(StaticProblem& problem, const PlatenLoading& loading, SparseSolver& solver,
                          const NewtonOptions& newton = {}, const IncrementObserver& observe = {});

}  // namespace latmpm::statics
