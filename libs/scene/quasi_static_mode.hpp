// Quasi-static mode (issue 14; docs/tradeoff.md, "Quasi-static mode"): [time] quasi_static =
// { load_error = 0.03 } picks the mass scaling instead of the scene, the largest whose
// measured load error stays within the bound.
//
// Mass scaling s and loading rate v are one lever for a rate-independent material without
// gravity: ρ ü = ∇·σ(u) is unchanged by t → α t, ρ → α² ρ, v → v / α, so a run is fixed by the
// plate's Mach number M = v / c, c = √(P / (s ρ0)) the dilatational wave speed (P the P-wave
// modulus), and costs ∝ 1/M steps whichever of s or v moves it. The mode keeps the scene's
// loading rate (its time axis stays the test's) and sets s.
//
// Error model: measured on QUICK T2P30-E10 (uGIMP, rigid plates; pipelines/tradeoff/
// issue14-compare.py): the largest difference of the load at every 0.5 mm of travel from that
// of the run at half paper A's Mach number (ρ = 1.5 ρ0 at 100 mm/s, the quasi-static proxy),
// as a fraction of its peak load, against the Mach number over paper A's (ρ = 6 ρ0, 100 mm/s,
// E = 10 MPa, ν = 0.4: M_A = 1.71e-3). Between the measured points the error is interpolated
// linearly; beyond the largest (2 M_A) the mode does not go.
#pragma once
#include <string>

namespace latmpm {

struct Scene;

struct QuasiStaticChoice {
  double mass_scaling = 0;     // the pick
  double mach = 0;             // plate speed over the dilatational wave speed at that scaling
  double mach_ratio = 0;       // over paper A's Mach number
  double expected_error = 0;   // measured load error at that ratio (fraction of the peak load)
  std::string reason;          // one line for the log
};

// Paper A's Mach number: 100 mm/s, E = 10 MPa, ν = 0.4, ρ = 6 × 1050 kg/m³.
double paper_a_mach();
// The measured load error (fraction of the peak) at a Mach number `ratio` times paper A's,
// 0 at half of it; linear between the measured points.
double quasi_static_load_error(double ratio);
// The largest ratio whose measured error is within `bound` (capped at the largest measured).
double quasi_static_mach_ratio(double bound);
// The mode's pick for a scene with a driven body and deformable materials, for `bound`.
QuasiStaticChoice choose_quasi_static(const Scene& scene, double bound);

}  // namespace latmpm
