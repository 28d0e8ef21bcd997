#include "scene/quasi_static_mode.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "mpm/material.hpp"
#include "scene/scene.hpp"

namespace latmpm {
namespace {

// Measured (docs/tradeoff.md, "Quasi-static mode"): QUICK T2P30-E10, uGIMP, rigid plates with
// the one-cell slice, cfl 0.3, 100 mm/s, mass scaling 1.5 / 6 / 9 / 12 / 24 (ratio √(s / 6)):
// largest load difference at every 0.5 mm from the run at mass scaling 1.5, over its peak.
struct Point {
  double ratio, error;
};
constexpr std::array<Point, 5> measured = {{{0.5, 0.0}, {1.0, 0.0279}, {1.2247, 0.0417}, {1.4142, 0.0588}, {2.0, 0.1048}}};

}  // namespace

double paper_a_mach() {
  mpm::MaterialParameters paper_a;  // E = 10 MPa, ν = 0.4, ρ = 6 × 1050 kg/m³, plate at 100 mm/s
  paper_a.young_modulus = 10e6;
  paper_a.poisson_ratio = 0.4;
  return 0.1 / std::sqrt(paper_a.p_wave_modulus() / (6 * 1050.0));
}

double quasi_static_load_error(double ratio) {
  if (ratio <= measured.front().ratio) return 0;
  for (size_t i = 1; i < measured.size(); ++i)
    if (ratio <= measured[i].ratio) {
      const Point a = measured[i - 1], b = measured[i];
      return a.error + (b.error - a.error) * (ratio - a.ratio) / (b.ratio - a.ratio);
    }
  return measured.back().error;  // not measured beyond: the mode does not go there
}

double quasi_static_mach_ratio(double bound) {
  if (bound >= measured.back().error) return measured.back().ratio;
  for (size_t i = 1; i < measured.size(); ++i)
    if (bound <= measured[i].error) {
      const Point a = measured[i - 1], b = measured[i];
      return a.ratio + (b.ratio - a.ratio) * (bound - a.error) / (b.error - a.error);
    }
  return measured.back().ratio;
}

QuasiStaticChoice choose_quasi_static(const Scene& scene, double bound) {
  // The plate: the one driven body (check_consistency: run.end.plate_displacement needs one).
  double speed = 0;
  for (const auto& b : scene.bodies)
    if (b.role == BodyRole::driven) speed = std::max(speed, b.velocity.norm());
  for (const auto& r : scene.rigid_bodies)  // a scheduled platen: its fastest knot
    if (r.motion == mpm::RigidMotion::driven || r.motion == mpm::RigidMotion::scheduled)
      speed = std::max(speed, double(mpm::prescribed_max_speed(r)));
  // The fastest wave of the unscaled deformable materials sets the Mach number.
  double c0 = 0;
  for (const auto& b : scene.bodies)
    if (b.role == BodyRole::deformable)
      c0 = std::max(c0, std::sqrt(b.material.p_wave_modulus() / b.material.density));
  QuasiStaticChoice c;
  c.mach_ratio = quasi_static_mach_ratio(bound);
  c.mach = c.mach_ratio * paper_a_mach();
  // M = v √s / c0  →  s = (M c0 / v)².
  c.mass_scaling = speed > 0 && c0 > 0 ? std::pow(c.mach * c0 / speed, 2) : 1;
  c.expected_error = quasi_static_load_error(c.mach_ratio);
  char text[400];
  std::snprintf(text, sizeof text,
                "quasi-static mode: load error bound %.3g %% of the peak; picked mass scaling %.3g (plate Mach "
                "number %.3g = %.3g x paper A's 100 mm/s at rho = 6 rho0), measured load error %.3g %% at that "
                "Mach number against a run at half paper A's (QUICK T2P30-E10, docs/tradeoff.md)%s",
                100 * bound, c.mass_scaling, c.mach, c.mach_ratio, 100 * c.expected_error,
                bound >= measured.back().error ? "; capped at the largest Mach number measured" : "");
  c.reason = text;
  return c;
}

}  // namespace latmpm
