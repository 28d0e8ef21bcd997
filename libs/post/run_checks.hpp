// How far a run can be trusted, from its series (checks.csv; make extremes reads it):
//   energy_balance_error  |KE + SE − W| / W at the last row (kinetic, strain energy, external
//                         work of the series): small when the scheme conserves energy
//   balance_5pct_strain   travel / gauge length at the first row where that error passes 5 %
//                         (rows with W > 1e-3 W_end); NaN when it never does or no gauge length
//   ke_over_se            the largest KE / SE over the second half of the travel: small when the
//                         run is quasi-static
//   load_ripple           N, root-mean-square of the load about its mean over the last quarter
//                         of the travel (the explicit solver's ringing after buckling)
//   final_load            N, the load of the last row
//   energy_secant_stiffness  N/m, 2 SE / u² at the last row: the stiffness of the linear
//                         specimen that stores the run's strain energy at its travel (a reading of
//                         the stiffness from the energy, beside the load's initial_stiffness)
//   energy_error_over_work  the solver's own balance at the last row, signed: the series'
//                         energy_error (every energy it books, docs/scene.md) over W; positive
//                         when the scheme made energy. NaN when W is 0
//   impact_energy_error   impact runs (series with flyer_kinetic_energy): the whole system's
//                         balance, the flyer's kinetic + potential energy and the material's
//                         kinetic + strain + dissipated energies (the series' energy_error,
//                         docs/scene.md), over the energy at the start (the impact energy), at
//                         the last row, signed; and impact_energy_error_worst, the largest
//                         |energy_error| over the run over the same. energy_balance_error above
//                         is the material's balance against the flyer's work on it: in an
//                         impact that work falls back towards 0 as the flyer rebounds, so it
//                         is no measure of how well the impact's energy closes
// Each is NaN where the series lacks the columns it needs.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "post/run_analysis.hpp"

namespace latmpm::post {

struct RunChecks {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double energy_balance_error = none, balance_5pct_strain = none, ke_over_se = none;
  double load_ripple = none, final_load = none, energy_error_over_work = none, energy_secant_stiffness = none;
  double impact_energy_error = none, impact_energy_error_worst = none;
};

RunChecks run_checks(const RunAnalysis& run);
// The largest KE / SE over the rows at or beyond half of the final travel where SE > 0; or
// over the rows with travel in [from, to].
double kinetic_over_strain(const RunAnalysis& run);
double kinetic_over_strain(const RunAnalysis& run, double from, double to);

// checks.csv: one row per run.
std::string checks_csv(const std::vector<RunAnalysis>& runs, const std::vector<std::string>& provenance_comments);

}  // namespace latmpm::post
