#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "post/compression_metrics.hpp"

using namespace latmpm::post;

namespace {

// A cellular-solid curve with every feature known in closed form (SI):
//   0 ≤ u ≤ 1 mm      F = k u, k = 2000 N/m          (linear, first peak 2 N at 1 mm)
//   1 < u ≤ 2 mm      F falls linearly to 1.5 N        (post-peak softening, a 25 % drop)
//   2 < u ≤ 16 mm     F = 1.5 N                        (plateau)
//   u > 16 mm         F = 1.5 + a (u − 16 mm)², a = 1e5 N/m²  (densification)
struct Foam {
  static constexpr double k = 2000, a = 1e5, plateau = 1.5, u_dens = 16e-3;
  static double load(double u) {
    if (u <= 1e-3) return k * u;
    if (u <= 2e-3) return 2.0 - 0.5 * (u - 1e-3) / 1e-3;
    if (u <= u_dens) return plateau;
    return plateau + a * (u - u_dens) * (u - u_dens);
  }
  // ∫₀ᵘ F du, exactly.
  static double work(double u) {
    if (u <= 1e-3) return 0.5 * k * u * u;
    if (u <= 2e-3) return 1e-3 + (u - 1e-3) * (2.0 + load(u)) / 2;
    if (u <= u_dens) return 1e-3 + 1.75e-3 + plateau * (u - 2e-3);
    const double s = u - u_dens;
    return work(u_dens) + plateau * s + a * s * s * s / 3;
  }
  // Maximum of the efficiency W/F: F² = W F′, solved by bisection on the exact functions.
  static double densification_onset() {
    auto g = [](double u) { return load(u) * load(u) - work(u) * 2 * a * (u - u_dens); };
    double lo = u_dens + 1e-9, hi = u_dens + 10e-3;
    for (int i = 0; i < 200; ++i) (g(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
    return 0.5 * (lo + hi);
  }
};

LoadHistory sample(double (*load)(double), double u_end, double du, double noise = 0, double noise_period = 1) {
  LoadHistory h;
  const size_t n = size_t(std::lround(u_end / du));
  for (size_t i = 0; i <= n; ++i) {
    const double u = du * double(i);
    h.displacement.push_back(u);
    h.time.push_back(u / 0.1);  // 100 mm/s
    h.load.push_back(load(u) + noise * std::sin(2 * M_PI * u / noise_period));
  }
  return h;
}

constexpr double gauge = 40e-3, mass = 1.05e-5;  // m, kg

}  // namespace

TEST_CASE("Compression metrics of an analytic foam curve match their closed forms", "[post]") {
  const LoadHistory h = sample(Foam::load, 30e-3, 1e-5);
  const CompressionMetrics m = compression_metrics(h, gauge, mass);
  const double bin = 1e-3 * gauge;  // 0.1 % strain

  CHECK(m.stiffness == Approx(Foam::k).epsilon(1e-9));
  CHECK(m.fit_to == Approx(0.5 * m.first_peak_displacement));
  CHECK(std::abs(m.first_peak_displacement - 1e-3) <= bin);
  CHECK(std::abs(m.first_peak_load - 2.0) <= Foam::k * bin);
  CHECK(m.peak_load == Approx(Foam::load(30e-3)).epsilon(1e-12));
  CHECK(m.peak_displacement == Approx(30e-3));
  CHECK(m.peak_time == Approx(0.3));
  CHECK(m.plateau_from == Approx(0.2 * gauge));
  CHECK(m.plateau_to == Approx(0.3 * gauge));
  CHECK(m.plateau_load == Approx(Foam::plateau).epsilon(1e-12));
  // The onset sits on the 0.1 %-strain grid of the binned curve: within one bin of the root.
  const double onset = Foam::densification_onset();
  CHECK(std::abs(m.densification_displacement - onset) <= bin);
  CHECK(m.densification_strain == Approx(m.densification_displacement / gauge));
  // Trapezoid error on the parabola: (b − a) h² F''/12 ≈ 2e-8 J of 0.1 J.
  CHECK(m.energy == Approx(Foam::work(30e-3)).epsilon(1e-6));
  CHECK(m.energy_to_densification == Approx(Foam::work(m.densification_displacement)).epsilon(1e-6));
  CHECK(m.sea == Approx(m.energy / mass));
  CHECK(m.sea_to_densification == Approx(m.energy_to_densification / mass));
}

TEST_CASE("Compression metrics see through the solver's oscillation", "[post]") {
  // A 0.1 N ripple with a 0.013 mm period (a few rows), as explicit runs show.
  const LoadHistory h = sample(Foam::load, 30e-3, 1e-6, 0.1, 0.013e-3);
  const CompressionMetrics m = compression_metrics(h, gauge, mass);
  const double bin = 1e-3 * gauge;
  // Least squares over 0.5 mm averages ~40 ripple periods: slope error ≲ ripple/(range·√N).
  CHECK(m.stiffness == Approx(Foam::k).epsilon(0.01));
  CHECK(std::abs(m.first_peak_displacement - 1e-3) <= bin);
  // The plateau mean over 4 mm integrates whole ripple periods up to a fraction of one.
  CHECK(m.plateau_load == Approx(Foam::plateau).epsilon(1e-3));
  // Binning damps the ripple to ≈ 0.1 N · period / (π · bin) ≈ 0.01 N: the efficiency maximum
  // stays on the bin nearest the exact onset.
  CHECK(std::abs(m.densification_displacement - Foam::densification_onset()) <= bin);
  CHECK(m.energy == Approx(Foam::work(30e-3)).epsilon(1e-4));
}

TEST_CASE("A curve without a drop has no first peak and fits its stiffness over 2 % strain", "[post]") {
  // Bilinear hardening: 2000 N/m to 2 mm, then 200 N/m.
  const LoadHistory h = sample([](double u) { return u <= 2e-3 ? 2000 * u : 4 + 200 * (u - 2e-3); }, 20e-3, 1e-5);
  const CompressionMetrics m = compression_metrics(h, gauge, mass);
  CHECK(std::isnan(m.first_peak_load));
  CHECK(m.fit_to == Approx(0.02 * gauge));
  CHECK(m.stiffness == Approx(2000).epsilon(1e-9));
  CHECK(m.peak_displacement == Approx(20e-3));
  // The efficiency of a hardening curve rises to the end: no densification onset in the run.
  CHECK(std::isnan(m.densification_displacement));
  bool said = false;
  for (const auto& n : m.notes) said = said || n.find("densification onset: not reached") != std::string::npos;
  CHECK(said);
}

TEST_CASE("Metrics that the run does not reach are NaN with a note", "[post]") {
  const LoadHistory h = sample(Foam::load, 10e-3, 1e-5);  // ends at 25 % strain
  const CompressionMetrics m = compression_metrics(h, gauge, std::nan(""));
  CHECK(std::isnan(m.plateau_load));
  CHECK(std::isnan(m.sea));
  CHECK(std::isfinite(m.energy));
  std::string notes;
  for (const auto& n : m.notes) notes += n + "\n";
  CHECK_THAT(notes, Catch::Contains("the run ends at 25 % strain, before 30 %"));
  CHECK_THAT(notes, Catch::Contains("SEA: specimen mass unknown"));

  const CompressionMetrics no_gauge = compression_metrics(h, std::nan(""), mass);
  CHECK(std::isnan(no_gauge.plateau_load));
  CHECK(std::isnan(no_gauge.densification_strain));
}

TEST_CASE("An explicit fit range and plateau strains are used as given", "[post]") {
  const LoadHistory h = sample(Foam::load, 30e-3, 1e-5);
  CompressionSettings s;
  s.fit_from = 1.2e-3, s.fit_to = 1.8e-3;  // the softening branch: slope −500 N/m
  s.plateau_from_strain = 0.2, s.plateau_to_strain = 0.4;  // 8–16 mm: still the flat plateau
  const CompressionMetrics m = compression_metrics(h, gauge, mass, s);
  CHECK(m.stiffness == Approx(-500).epsilon(1e-9));
  CHECK(m.plateau_load == Approx(1.5).epsilon(1e-12));
  // The same range as fractions of the 30 mm travel (--fit-range 4%:6%).
  CompressionSettings fractions;
  fractions.fit_from_fraction = 0.04, fractions.fit_to_fraction = 0.06;
  const CompressionMetrics f = compression_metrics(h, gauge, mass, fractions);
  CHECK(f.fit_from == Approx(1.2e-3).epsilon(1e-12));
  CHECK(f.fit_to == Approx(1.8e-3).epsilon(1e-12));
  CHECK(f.stiffness == Approx(-500).epsilon(1e-9));
  s.plateau_to_strain = 0.5;  // 8–20 mm: includes densification, mean = 1.5 + a ∫(u−16)² / 12 mm
  const double expected = 1.5 + Foam::a * std::pow(4e-3, 3) / 3 / 12e-3;
  CHECK(compression_metrics(h, gauge, mass, s).plateau_load == Approx(expected).epsilon(1e-6));
}

TEST_CASE("The energy efficiency of a linear curve is half the travel", "[post]") {
  // W = k u²/2, F = k u → W/F = u/2 (undefined at F = 0).
  const std::vector<double> u{0, 1, 2, 3}, f{0, 5, 10, 15};
  const std::vector<double> eta = efficiency_length(u, f);
  CHECK(std::isnan(eta[0]));
  for (size_t i = 1; i < u.size(); ++i) CHECK(eta[i] == Approx(u[i] / 2));
}

TEST_CASE("A start-up spike is not taken for the first peak, the fit or the densification", "[post]") {
  // The foam curve with the spike of a platen set moving at once: a triangle of 1.2 N over
  // the first 0.12 mm (0.3 % strain), peaking at 0.06 mm; the quasi-static curve climbs past
  // it at 0.66 mm.
  static auto spiked = [](double u) { return Foam::load(u) + 1.2 * std::max(0.0, 1 - std::abs(u - 0.06e-3) / 0.06e-3); };
  const LoadHistory h = sample([](double u) { return spiked(u); }, 30e-3, 1e-5);
  const double bin = 1e-3 * gauge;
  const CompressionMetrics m = compression_metrics(h, gauge, mass);
  CHECK(m.transient_end > 0.12e-3);
  CHECK(m.transient_end < 0.12e-3 + 2 * bin);
  CHECK(std::abs(m.first_peak_displacement - 1e-3) <= bin);  // not the spike at 0.06 mm
  CHECK(m.stiffness == Approx(Foam::k).epsilon(1e-9));        // the fit starts after it
  CHECK(m.fit_from == Approx(m.transient_end));
  CHECK(m.peak_displacement == Approx(30e-3));
  // The work counts from the transient's end: the onset moves by less than two bins.
  CHECK(std::abs(m.densification_displacement - Foam::densification_onset()) <= 2 * bin);
  CHECK(m.energy == Approx(Foam::work(30e-3) + 1.2 * 0.06e-3).epsilon(1e-4));  // the spike's work counts
  bool said = false;
  for (const auto& n : m.notes) said = said || n.find("start-up transient") != std::string::npos;
  CHECK(said);
  // Ringing after the spike (a decaying oscillation of 0.1 mm wavelength and 10 % amplitude
  // over the first 0.5 mm) is not a first peak either: each maximum is exceeded again at once.
  static auto ringing = [](double u) {
    return spiked(u) * (1 + (u < 0.5e-3 ? 0.1 * std::sin(2 * M_PI * u / 0.1e-3) * (1 - u / 0.5e-3) : 0.0));
  };
  const CompressionMetrics rung = compression_metrics(sample([](double u) { return ringing(u); }, 30e-3, 1e-5), gauge, mass);
  CHECK(std::abs(rung.first_peak_displacement - 1e-3) <= bin);
  CHECK(std::abs(rung.densification_displacement - Foam::densification_onset()) <= 2 * bin);
  // Switching the detection off gives the old reading: the spike as the first peak.
  CompressionSettings off;
  off.transient_window = 0;
  CHECK(compression_metrics(h, gauge, mass, off).first_peak_displacement < 0.1e-3);
}
