// A trilinear hexahedron (8-node brick) as a particle domain: paper B's CPDI1 domains come
// from finite-element meshes (Sec. 2.2), so a domain is a general trilinear brick, not a
// parallelepiped. Vertex order is gmsh's (and VTK's): 0–3 the face ζ = −1 counter-clockwise
// seen from +ζ starting at (−1,−1), 4–7 the face ζ = +1 in the same order.
//
// The integrals of Eq. 7 — ∫ Q_α dv and ∫ grad Q_α dv over the domain — use 2×2×2 Gauss
// points, which integrate them exactly: det J of a trilinear map and its cofactors are at
// most quadratic in each reference coordinate, times the at most linear Q_α or ∂Q_α/∂ξ.
#pragma once
#include <Eigen/Core>
#include <array>

namespace latmpm {

using HexVertices = std::array<Eigen::Vector3d, 8>;

struct HexIntegrals {
  double volume = 0;                                // ∫ dv, m³
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // (1/v) ∫ x dv, m
  std::array<double, 8> vertex_weight{};            // ∫ Q_α dv, m³ (sums to the volume)
  std::array<Eigen::Vector3d, 8> vertex_gradient;    // ∫ grad Q_α dv, m² (sums to zero); hex_integrals sets it
  double min_jacobian = 0;  // smallest det J at the Gauss points and vertices: ≤ 0 means inverted
};

// Reference coordinates (±1) of vertex α.
Eigen::Vector3d hex_reference_vertex(int alpha);

// Exact integrals of the trilinear hexahedron with these vertices (any shape; an inverted
// one gives min_jacobian ≤ 0 and is the caller's to refuse).
HexIntegrals hex_integrals(const HexVertices& vertices);

}  // namespace latmpm
