// CPDI1 shape functions (paper B Eq. 7; Sadeghirad, Brannon & Burghardt 2011, IJNME 86:1435)
// over trilinear hexahedral particle domains:
//   S_I  = (1/v) Σ_α (∫ Q_α dv) N̄_I(x_α),     ∇S_I = (1/v) Σ_α (∫ grad Q_α dv) N̄_I(x_α),
// with N̄_I the grid's trilinear tent functions evaluated at the domain's eight vertices x_α.
// CPDI1: the vertices move with the particle's deformation gradient, x_α = x_p + F (X_α − X_p)
// (paper B Fig. 2), not with the grid velocity (that would be CPDI2).
//
// S_I sums to 1, Σ S_I x_I is the domain's centroid and Σ x_I ⊗ ∇S_I = I for any domain
// (tests/mpm/test_cpdi.cpp), because the tent functions reproduce linear fields and the
// integrals are exact (points/hexahedron.hpp). The stencil is the box of grid nodes the eight
// vertices touch, so its size varies with the domain's extent.
#pragma once
#include <array>
#include <vector>

#include "mpm/real.hpp"
#include "points/hexahedron.hpp"

namespace latmpm::mpm {

struct CpdiStencil {
  Eigen::Vector3i first_node = Eigen::Vector3i::Zero();  // node (i, j, k) sits at x = (i, j, k)·h
  Eigen::Vector3i node_count = Eigen::Vector3i::Zero();  // nodes along x, y, z
  std::vector<Real> weight;    // S_I, x fastest, then y, then z
  std::vector<Vec3> gradient;  // ∇S_I, 1/m
  Real volume = 0;             // v, m³, the domain's exact volume

  size_t size() const { return weight.size(); }
  Eigen::Vector3i node(size_t n) const;  // grid index of entry n
};

// Eq. 7 vertex by vertex, the form the transfers can loop over: vertex α adds to the eight
// nodes of its grid cell S_I += weight · tent[c] and ∇S_I += gradient · tent[c], with
// weight = ∫Q_α dv / v and gradient = ∫grad Q_α dv / v. The eight vertices' sums are the
// stencil; vertices sharing nodes accumulate.
struct CpdiVertexStencil {
  Eigen::Vector3i cell = Eigen::Vector3i::Zero();  // grid cell of the vertex: its lowest node
  Real tent[8] = {};  // N̄_I(x_α) of node cell + (c&1, c>>1&1, c>>2)
  Real weight = 0;    // ∫Q_α dv / v
  Vec3 gradient = Vec3::Zero();  // ∫grad Q_α dv / v, 1/m
  Eigen::Vector3i node(int c) const { return cell + Eigen::Vector3i(c & 1, (c >> 1) & 1, c >> 2); }
};
using CpdiVertexStencils = std::array<CpdiVertexStencil, 8>;
CpdiVertexStencils cpdi_vertex_stencils(const HexVertices& vertices, const std::array<Real, 8>& weight,
                                        const std::array<Vec3, 8>& gradient, Real cell_size);

// The domain's vertices after the particle moved to `position` with deformation gradient F,
// from their offsets to the centroid in the reference configuration (CPDI1, Fig. 2).
HexVertices convected_vertices(const Vec3& position, const Mat3& F, const HexVertices& reference_offsets);

// Eq. 7 for a domain with these (current) vertices on a grid of spacing h (m). Throws
// NumericalError for an inverted domain (det J ≤ 0 somewhere).
CpdiStencil cpdi_stencil(const HexVertices& vertices, Real cell_size);

// What a CPDI1 particle keeps of its reference domain. Because the domain deforms
// affinely with F, its integrals follow without new quadrature: v = J v0, ∫Q_α dv = J ∫Q_α dV,
// ∫grad Q_α dv = J F⁻ᵀ ∫Grad Q_α dV; the J cancels against 1/v in Eq. 7.
struct CpdiDomain {
  HexVertices offsets;                        // X_α − X_p (X_p the centroid), m
  std::array<Real, 8> weight_fraction{};      // ∫Q_α dV / V0
  std::array<Vec3, 8> gradient_per_volume;    // ∫Grad Q_α dV / V0, 1/m
  Real volume = 0;                            // V0, m³
};
// Throws NumericalError for an inverted hexahedron.
CpdiDomain make_cpdi_domain(const HexVertices& reference_vertices);
// Eq. 7 for the domain convected to `position` with deformation gradient F (same result as
// cpdi_stencil(convected_vertices(...)) to rounding, without the quadrature).
CpdiStencil cpdi_stencil(const CpdiDomain& domain, const Vec3& position, const Mat3& F, Real cell_size);

}  // namespace latmpm::mpm
