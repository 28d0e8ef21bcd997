#include "post/run_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "post/post_report.hpp"

namespace latmpm::post {

double kinetic_over_strain(const RunAnalysis& a, double from, double to) {
  const SeriesTable& s = a.run.series;
  const auto& u = a.history.displacement;
  if (!s.has("kinetic_energy") || !s.has("strain_energy") || u.empty()) return RunChecks::none;
  const auto& ke = s.column("kinetic_energy", a.run.path);
  const auto& se = s.column("strain_energy", a.run.path);
  double ratio = 0;
  for (size_t i = 0; i < u.size() && i < ke.size(); ++i)
    if (u[i] >= from && u[i] <= to && se[i] > 0) ratio = std::max(ratio, ke[i] / se[i]);
  return ratio;
}

double kinetic_over_strain(const RunAnalysis& a) {
  const auto& u = a.history.displacement;
  return u.empty() ? RunChecks::none : kinetic_over_strain(a, 0.5 * u.back(), INFINITY);
}

namespace {

// The impact's whole-system balance (issue 16: flyer kinetic + potential + material strain +
// kinetic + dissipated): the solver's energy_error books all of them, so it is divided by the
// total at the start (the flyer's kinetic energy, plus any the material starts with).
void impact_energy_balance(const SeriesTable& s, const std::string& path, RunChecks& c) {
  if (!s.has("flyer_kinetic_energy") || !s.has("energy_error") || s.rows() == 0) return;
  double initial = s.column("flyer_kinetic_energy", path).front();
  for (const char* name : {"flyer_potential_energy", "kinetic_energy", "strain_energy"})
    if (s.has(name)) initial += s.column(name, path).front();
  if (initial <= 0) return;
  const auto& error = s.column("energy_error", path);
  c.impact_energy_error = error.back() / initial;
  double worst = 0;
  for (double e : error) worst = std::max(worst, std::abs(e));
  c.impact_energy_error_worst = worst / initial;
}

}  // namespace

RunChecks run_checks(const RunAnalysis& a) {
  RunChecks c;
  const SeriesTable& s = a.run.series;
  const auto& u = a.history.displacement;
  const auto& f = a.history.load;
  if (!f.empty()) c.final_load = f.back();
  c.ke_over_se = kinetic_over_strain(a);
  if (s.has("energy_error") && s.has("external_work") && s.rows() > 0) {
    const double w = s.column("external_work", a.run.path).back();
    if (w != 0) c.energy_error_over_work = s.column("energy_error", a.run.path).back() / w;
  }
  impact_energy_balance(s, a.run.path, c);
  if (s.has("strain_energy") && !u.empty() && u.back() > 0)
    c.energy_secant_stiffness = 2 * s.column("strain_energy", a.run.path).back() / (u.back() * u.back());
  if (s.has("kinetic_energy") && s.has("strain_energy") && s.has("external_work") && !u.empty()) {
    const auto& ke = s.column("kinetic_energy", a.run.path);
    const auto& se = s.column("strain_energy", a.run.path);
    const auto& w = s.column("external_work", a.run.path);
    // Plastic work (J2 runs), the penalty springs' energy and friction's loss (penalty
    // contact runs) are energy the work put in, not an imbalance; so is the kinetic energy
    // the FLIP/PIC blend removed (numerical, counted like the solver's energy_error, so that
    // what is left is the scheme's own error); older series lack them.
    std::vector<double> pd(w.size(), 0.0);
    for (const char* name :
         {"plastic_dissipation", "contact_energy", "friction_dissipation", "blend_dissipation", "transfer_dissipation"})
      if (s.has(name)) {
        const auto& column = s.column(name, a.run.path);
        for (size_t i = 0; i < std::min(pd.size(), column.size()); ++i) pd[i] += column[i];
      }
    const size_t n = std::min(u.size(), w.size());
    if (n > 0 && w[n - 1] != 0) {
      c.energy_balance_error = std::abs(ke[n - 1] + se[n - 1] + pd[n - 1] - w[n - 1]) / std::abs(w[n - 1]);
      for (size_t i = 0; i < n; ++i)
        if (w[i] > 1e-3 * w[n - 1] && std::abs(ke[i] + se[i] + pd[i] - w[i]) > 0.05 * std::abs(w[i])) {
          c.balance_5pct_strain = u[i] / a.run.specimen.gauge_length;
          break;
        }
    }
  }
  if (!u.empty() && u.back() > 0) {
    double sum = 0, squares = 0;
    size_t m = 0;
    for (size_t i = 0; i < u.size(); ++i)
      if (u[i] >= 0.75 * u.back()) sum += f[i], squares += f[i] * f[i], ++m;
    if (m > 0) c.load_ripple = std::sqrt(std::max(0.0, squares / double(m) - (sum / double(m)) * (sum / double(m))));
  }
  return c;
}

std::string checks_csv(const std::vector<RunAnalysis>& runs, const std::vector<std::string>& provenance_comments) {
  std::ostringstream out;
  for (const auto& line : provenance_comments) out << "# " << line << "\n";
  out << "# how far each run can be trusted (docs/post.md, \"Checks\")\n";
  out << "label,energy_balance_error[1],balance_5pct_strain[1],ke_over_se[1],load_ripple[N],final_load[N],energy_error_over_work[1],energy_secant_stiffness[N/mm],"
         "impact_energy_error[1],impact_energy_error_worst[1]\n";
  for (const RunAnalysis& a : runs) {
    const RunChecks c = run_checks(a);
    out << a.run.label << "," << number_text(c.energy_balance_error) << "," << number_text(c.balance_5pct_strain) << ","
        << number_text(c.ke_over_se) << "," << number_text(c.load_ripple) << "," << number_text(c.final_load) << ","
        << number_text(c.energy_error_over_work) << "," << number_text(c.energy_secant_stiffness * 1e-3) << ","
        << number_text(c.impact_energy_error) << "," << number_text(c.impact_energy_error_worst) << "\n";
  }
  return out.str();
}

}  // namespace latmpm::post
