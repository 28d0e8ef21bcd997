// Displacement-controlled loading (the static counterpart of the explicit solver's driven
// plate): a rigid platen moves in increments along `direction`; the band nodes it reaches
// take its displacement (all three components: no slip, like the explicit grid update),
// the supports' nodes stay at zero, and each increment is solved by projected Newton to the
// residual tolerance from the previous equilibrium. After each increment the true
// (unprojected) tangent is factorised: the static path ends at the first increment where it
// is not positive definite (a bifurcation or limit point: buckling), where the load falls
// (past a limit point; the only check where the true tangent is unusable, docs/statics.md)
// or where Newton fails; the travel there is bracketed by bisection. The check factorises
// with the Newton solver itself when that is direct (one analysis, one factor in memory:
// the next Newton step refactorises anyway), else with its own CHOLMOD.
#pragma once
#include <functional>
#include <string>
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
  int bisections = 6;                 // halvings of the bracket around the instability
  // Start each increment's Newton from the secant extrapolation of the last two equilibria
  // (from the last one where that inverts a point or does not converge).
  bool predictor = true;
};

struct PathPoint {
  Real travel = 0;          // m
  Real load = 0;            // N: force the platen exerts along its motion
  Real support_load = 0;    // N: force the supports exert against it
  Real energy = 0;          // J: stored elastic energy
  int newton_iterations = 0;  // including any spent from an abandoned prediction
  bool predicted = false;     // converged from the predictor's start
  int linear_iterations = 0;
  Real linear_residual = 0;  // ‖K d − r‖ / ‖r‖ of the last linear solve
  Real residual = 0;        // final relative residual
  Real min_jacobian = 1;
  bool stable = true;       // true tangent positive definite (or not checked)
};

struct PathReport {
  std::vector<PathPoint> points;  // the converged increments, in order (bisection included)
  bool ended = false;             // an instability or a failure ended the path before `travel`
  std::string end_reason;         // "tangent not positive definite", or Newton's failure
  Real end_travel = 0;            // m: middle of the final bracket (last stable, first unstable)
  Real end_load = 0;              // N: the load there (interpolated), or the last stable load
  Real last_stable_travel = 0;    // m: the last travel found stable
  Real last_stable_load = 0;      // N: the load there
  PhaseTime stability_check;      // true-tangent assemblies and factorisations after increments
};

// Called after each converged increment with its point and displacement field.
using IncrementObserver = std::function<void(const PathPoint&, const Vector&)>;

PathReport load_by_platen(StaticProblem& problem, const PlatenLoading& loading, SparseSolver& solver,
                          const NewtonOptions& newton = {}, const IncrementObserver& observe = {});

}  // namespace latmpm::statics
