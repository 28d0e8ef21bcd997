// The null-space filter on the particles' deformation gradients (Settings::null_space_filter).
//
// With more points than nodes, the particle-to-grid map P2G (b_I = Σ_p S_Ip m_p f_p) has a
// null space: point-to-point oscillating values that map to zero on every node (Gritton,
// Berzins & Kirby 2017, "Improving accuracy in the MPM method using a null space filter",
// Comput. Part. Mech., doi 10.1007/s40571-016-0134-3). A strain held in that part of F is
// invisible to the grid, which alone moves the body, so it can neither drive the body nor
// be unloaded: an elastic lattice released from its platens keeps it as a permanent set
// (docs/paper-b.md, "The recovery check, and the elastic lattice's permanent set").
//
// The filter replaces a body's F_p by the deformation gradient of the nearest reference map
// the grid can represent. F⁻¹ = ∂X/∂x is the gradient, in the current configuration, of the
// reference map X(x) (where the material at x started); the grid's fields are
// X(x) = Σ_I S_I(x) u_I with the run's own shape functions, so the filter takes
//   F̃_p⁻¹ = Σ_I u_I ⊗ ∇S_Ip,  u = argmin Σ_p m_p |F_p⁻¹ − Σ_I u_I ⊗ ∇S_Ip|²,
// i.e. K u = Gᵀ M F⁻¹ with K_IJ = Σ_p m_p ∇S_Ip·∇S_Jp (a mass-weighted Laplacian over the
// body's nodes, one right-hand side per component of X), solved directly (CHOLMOD's
// supernodal Cholesky; each diagonal raised by 1e-9 of itself, which only fixes the constant
// that no gradient sees).
// What it removes is orthogonal (mass inner product) to every gradient of a grid field: the
// part of F the nodal forces f_I = −Σ_p V_p σ_p ∇S_Ip see only through products of small
// terms, point-to-point oscillating. What it keeps (tests/mpm/test_null_space_filter.cpp):
// every F whose inverse is such a gradient (uniform F, rotations, at first order every F the
// grid's own velocities made: dF⁻¹ = −dt F⁻¹ L, L = Σ_I v_I ⊗ ∇S_Ip), the body's mass-
// weighted sum Σ_p m_p F_p⁻¹ (Σ_I x_I ⊗ ∇S_Ip = I turns the normal equations into it), and
// a second pass changes nothing. Gritton et al. filter with a local SVD of the mapping; a
// global least-squares projection is the filter's definition (their "global SVD" form)
// computed without a factorisation of the mapping. F⁻¹ and the gradients, not F's values and
// the interpolation, and global, not per cell: our choices, each measured (docs/solver.md,
// "Null-space filter").
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "mpm/particles.hpp"
#include "mpm/real.hpp"
#include "mpm/rigid_body.hpp"
#include "mpm/shape_function_kind.hpp"

namespace latmpm::mpm {

struct SolverState;
struct StepContext;

// One row per point: a 3×3 tensor (row-major), e.g. F⁻¹ (row a: the gradient of X_a).
using PointValues = std::vector<std::array<Real, 9>>;

// Replaces the tensors of `points` (indices into `ps`, one row each) by their projection onto
// the gradients of the grid's fields: the shape function's own gradients at the points'
// current positions (DDMP: its linear ones; CPDI1 refused, InputError), masses as weights.
// With `anchor` (one value per listed point: where it started, X_p) the tensors are read as
// F⁻¹ and the fitted field X(x) = Σ_I S_I(x) u_I is also asked to pass through the anchors:
//   u = argmin Σ_p m_p (|F_p⁻¹ − Σ_I u_I ⊗ ∇S_Ip|² + reference_map_weight / h² |X_p − Σ_I S_Ip u_I|²),
// so that the gradients returned are those of a map that sends the points back where they
// started: a strain F lost (or gained) against the positions comes back (or goes).
void project_onto_grid_gradients(const Particles& ps, const std::vector<uint32_t>& points, ShapeFunctionKind shape,
                                 Real h, PointValues& tensors, const std::vector<Vec3>* anchor = nullptr);

// The weight of the reference map's values against its gradients (NullSpaceFilter::reference_map),
// per cell: a mismatch of one cell in X counts as much as one of 1 in F⁻¹. So a pass follows
// the anchors over distances beyond about a cell, where F and the positions disagree by a
// drift, and leaves the within-cell detail to F. Why the anchor: on the paper-size elastic
// metal lattice the F-only filter left F with a sixteenth of the strain energy the positions
// showed during unloading (11.6 against 183 J) and the released lattice 0.66 mm short, at
// rest and stress-free (docs/paper-b.md, "The reference-map filter").
inline constexpr Real reference_map_weight = 1;

// Points whose surroundings within this many cells (a cube of half-width 1.5 h about the
// point) reach into a geometric rigid body (`rigid_bodies.*`) that presses the body keep
// their F and stay out of the fit. Where a rigid surface presses a body (a lattice's joints
// flattened on a platen) the parts that meet there rotate apart within a cell; a grid field's
// gradient cannot turn that fast, so the projection would average their F⁻¹, and an average
// of rotations is a strain: on the paper-size metal lattice one pass took points next to the
// platen from J ≈ 1 to 0.37–2.5 and the run blew up at 6.9 mm. Once the surface lets go the
// band is filtered again: kept out for good, it held its null-space strain and blew up later.
// The band's width and the alternatives tried: docs/solver.md, "Null-space filter".
inline constexpr Real rigid_surface_band_cells = 1.5;

// Whether `body` (rigid body number `index`, at the displacement of `state`) presses body `b`
// of the particles now. A penalty body: while one of b's points touches it
// (Particles::contact_body, the contact stage's attachment). A no-slip body, which acts
// through the nodes within a cell of it: while one of b's point domains comes within a cell.
bool rigid_body_presses(const RigidBodySettings& body, const RigidBodyState& state, size_t index,
                        const Particles& ps, int32_t b, Real h);

// True where the cube of half-width rigid_surface_band_cells · h about x reaches into `body`
// at the displacement of `state`.
bool near_rigid_surface(const RigidBodySettings& body, const RigidBodyState& state, const Vec3& x, Real h);

// The filter over every deformable body of the state, body by body (a body's points only,
// those near a rigid surface that presses it left out; the rigid bodies at their
// displacements of the step's start):
// F̃ written back, the stress taken again from it (materials whose stress is a function of
// F alone: the set-up refuses others). Returns the strain energy it removed (J; the energy
// ledger books it with the transfer's loss).
Real filter_deformation_gradients(SolverState& s, StepContext& c);

// The step's last stage (step_scheme): the filter over every deformable body after every
// `null_space_filter_every`-th step, its energy booked in the step's sums; nothing when the
// settings' filter is none.
void null_space_filter_stage(SolverState& s, StepContext& c);

}  // namespace latmpm::mpm
