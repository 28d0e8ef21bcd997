// How much of a material point's sub-cell (a cube of edge Δ = h/ppc centred on the point)
// lies inside the solid, from the signed distance φ at the point (negative inside) and the
// sum of principal curvatures κ = ∇²φ of the surface there.
//
// Planar part: across a flat interface the fraction falls linearly from 1 to 0 while φ goes
// from −Δ/2 to +Δ/2, f = ½ − φ/Δ. It is exact for faces parallel to the grid, and for any
// orientation its error is odd in φ, so it cancels over the surface (∫(f − H(−φ)) dφ = 0).
// Curvature part: summed over a curved surface the planar rule over-counts, because the
// level sets of φ grow in area outward, A(φ) = A₀(1 + κφ + …). The excess per unit area is
// κ ∫ φ (f − H(−φ)) dφ = κΔ²/24, carried by the 1/Δ² points per unit area inside the band,
// so each band point gives back κΔ/24. For a sphere of radius R this removes an over-count
// of Δ²/(4R²) of the volume (1.6 % at four points per radius); what remains is O(Δ³/R³).
// (Derivation and measured errors: docs/voxelize.md.)
#pragma once
#include <algorithm>

namespace latmpm {

// `phi`: signed distance at the point (m); `curvature`: ∇²φ (1/m); `spacing`: Δ (m).
inline double sub_cell_fraction(double phi, double curvature, double spacing) {
  if (phi <= -0.5 * spacing) return 1.0;
  if (phi >= 0.5 * spacing) return 0.0;
  // κΔ beyond ±3 only happens at creases and corners, where ∇²φ is a numerical spike.
  const double kappa_delta = std::clamp(curvature * spacing, -3.0, 3.0);
  return std::clamp(0.5 - phi / spacing - kappa_delta / 24.0, 0.0, 1.0);
}

}  // namespace latmpm
