#include <catch2/catch.hpp>

#include <cmath>

#include "post/column_metrics.hpp"
#include "post/impact_metrics.hpp"

using namespace latmpm::post;

TEST_CASE("The Euler load of paper A's thin column is 0.496 N clamped-clamped", "[post]") {
  // By hand: t = 1.6 mm, L = 16 mm, E = 10 MPa. I = π t⁴/64 = 3.21699e-13 m⁴,
  // π² E I = 3.17502e-5 N m², (K L)² = (0.5 · 0.016)² = 6.4e-5 m² → 0.496100 N.
  CHECK(euler_load(10e6, 1.6e-3, 16e-3, 0.5) == Approx(0.496100).epsilon(1e-5));
  // Thicker column: P ∝ t⁴ → (2.4/1.6)⁴ = 5.0625 times.
  CHECK(euler_load(10e6, 2.4e-3, 16e-3, 0.5) == Approx(0.496100 * 5.0625).epsilon(1e-5));
}

TEST_CASE("The Euler load scales with the effective-length factor as 1/K²", "[post]") {
  const double k = GENERATE(0.5, 0.7, 1.0, 2.0);
  CHECK(euler_load(8e6, 2e-3, 10e-3, k) * k * k == Approx(euler_load(8e6, 2e-3, 10e-3, 1.0)).epsilon(1e-12));
}

TEST_CASE("Column metrics compare the peak and the post-buckling load with the Euler load", "[post]") {
  // Loads up linearly to twice the Euler load at 1 mm, then sits on the Euler load from 1.5 mm to 4 mm.
  const double pe = euler_load(10e6, 1.6e-3, 16e-3, 0.5);
  LoadHistory h;
  for (int i = 0; i <= 400; ++i) {
    const double u = 1e-5 * i;
    h.displacement.push_back(u);
    h.time.push_back(u / 0.1);
    h.load.push_back(u <= 1e-3 ? 2 * pe * u / 1e-3 : u <= 1.5e-3 ? 2 * pe - pe * (u - 1e-3) / 0.5e-3 : pe);
  }
  const ColumnMetrics m = column_metrics(h, 10e6, 1.6e-3, 16e-3);
  CHECK(m.k == 0.5);
  CHECK(m.euler_load == Approx(pe));
  CHECK(m.peak_ratio == Approx(2).epsilon(1e-12));
  CHECK(m.post_buckling_load == Approx(pe).epsilon(1e-12));
  CHECK(m.post_buckling_ratio == Approx(1).epsilon(1e-12));

  const ColumnMetrics unknown = column_metrics(h, 10e6, std::nan(""), 16e-3);
  CHECK(std::isnan(unknown.euler_load));
  CHECK(std::isnan(unknown.peak_ratio));
  CHECK(unknown.peak_load == Approx(2 * pe));
  REQUIRE_FALSE(unknown.notes.empty());
}

namespace {

// A flyer of mass m meeting a linear spring k at speed v0: v = v0 cos ωt, F = m v0 ω sin ωt,
// ω = √(k/m), reversal at π/(2ω). After the reversal the lattice gives back a fraction e of
// the speed: v = −e v0 sin(ω(t − t_r)) (an idealised lossy unloading), no gravity.
ImpactHistory spring_impact(double v0, double e, double sign, bool with_potential) {
  const double m = 10, k = 4e4, w = std::sqrt(k / m), tr = M_PI / (2 * w);
  ImpactHistory h;
  for (int i = 0; i <= 2000; ++i) {
    const double t = 2 * tr * i / 2000.0;
    const double v = t <= tr ? v0 * std::cos(w * t) : -e * v0 * std::sin(w * (t - tr));
    h.time.push_back(t);
    h.velocity.push_back(sign * v);
    h.load.push_back(t <= tr ? m * v0 * w * std::sin(w * t) : m * e * v0 * w * std::cos(w * (t - tr)));
    h.kinetic_energy.push_back(0.5 * m * v * v);
    if (with_potential) h.potential_energy.push_back(0.0);
  }
  return h;
}

}  // namespace

TEST_CASE("Impact metrics of a spring impact match the closed form in either sign convention", "[post]") {
  const double v0 = 2, e = 0.6, m = 10, w = std::sqrt(4e4 / m), tr = M_PI / (2 * w);
  const double sign = GENERATE(1.0, -1.0);
  const ImpactMetrics r = impact_metrics(spring_impact(v0, e, sign, true));
  CHECK(r.impact_speed == Approx(v0));
  CHECK(r.peak_load == Approx(m * v0 * w).epsilon(1e-5));
  CHECK(r.peak_time == Approx(tr).epsilon(1e-9));
  // Linear interpolation of v between rows: error ≲ ω² dt² / 8 relative.
  CHECK(r.reversal_time == Approx(tr).epsilon(1e-5));
  CHECK(r.rebound_speed == Approx(e * v0).epsilon(1e-5));
  CHECK(r.energy_absorbed == Approx(0.5 * m * v0 * v0 * (1 - e * e)).epsilon(1e-6));
  CHECK(r.energy_absorbed_at_reversal == Approx(0.5 * m * v0 * v0).epsilon(1e-6));
  CHECK(r.notes.empty());
}

TEST_CASE("Impact metrics without flyer columns say what is missing", "[post]") {
  ImpactHistory h = spring_impact(2, 0.6, 1, false);
  const ImpactMetrics kinetic_only = impact_metrics(h);
  CHECK(std::isfinite(kinetic_only.energy_absorbed));
  REQUIRE(kinetic_only.notes.size() == 1);
  CHECK_THAT(kinetic_only.notes[0], Catch::Contains("no flyer_potential_energy"));

  h.velocity.clear();
  h.kinetic_energy.clear();
  const ImpactMetrics bare = impact_metrics(h);
  CHECK(std::isfinite(bare.peak_load));
  CHECK(std::isnan(bare.reversal_time));
  CHECK(std::isnan(bare.energy_absorbed));
  REQUIRE_FALSE(bare.notes.empty());
  CHECK_THAT(bare.notes[0], Catch::Contains("no flyer_velocity column"));
}

TEST_CASE("A flyer that never turns has no reversal time or rebound speed", "[post]") {
  ImpactHistory h = spring_impact(2, 0.6, 1, true);
  const size_t half = h.time.size() / 2 - 10;  // stop before the reversal
  for (auto* v : {&h.time, &h.velocity, &h.load, &h.kinetic_energy, &h.potential_energy}) v->resize(half);
  const ImpactMetrics r = impact_metrics(h);
  CHECK(std::isnan(r.reversal_time));
  CHECK(std::isnan(r.rebound_speed));
  CHECK(std::isnan(r.energy_absorbed_at_reversal));
  CHECK(r.energy_absorbed > 0);
}
