// Solver settings that are not per body: discretisation, scheme, time step, loads, checks.
// All dimensional values SI. docs/solver.md explains each choice.
#pragma once
#include <string>
#include <vector>

#include "mpm/field_contact_settings.hpp"
#include "mpm/real.hpp"
#include "mpm/shape_ddmp.hpp"
#include "mpm/shape_function_kind.hpp"

namespace latmpm::mpm {

// Order of the stress update within a step (Bardenhagen 2002; Nairn 2003; Paper B Sec. 2:
// USL). USL: stress from the new grid velocity at the end of the step. USF: stress from the
// old grid velocity before the nodal forces are formed. MUSL: USL with the particle
// momentum mapped back to the grid before the velocity gradient is taken.
enum class UpdateScheme { usl, usf, musl };
std::string to_string(UpdateScheme scheme);
std::vector<std::string> update_scheme_names();  // names.cpp
UpdateScheme parse_update_scheme(const std::string& name, const std::string& where = "",
                                 const std::string& field = "");
// The scheme a run takes unless it names one: MUSL for linear shapes, USL otherwise (names.cpp).
UpdateScheme default_scheme(ShapeFunctionKind shape);

// What the step filters out of the particles' state after each gather (null_space_filter.hpp):
// nothing, or the part of F in the null space of the particle-to-grid map (Gritton, Berzins &
// Kirby 2017), which the grid can neither see nor unload: `deformation` projects F⁻¹ alone onto
// the gradients of the grid's fields; `reference_map` also anchors the fitted field to where
// the points started, so F follows the positions back (a drift of F from them is removed too).
enum class NullSpaceFilter { none, deformation, reference_map };
std::string to_string(NullSpaceFilter filter);
std::vector<std::string> null_space_filter_names();  // names.cpp
NullSpaceFilter parse_null_space_filter(const std::string& name, const std::string& where = "",
                                        const std::string& field = "");

struct Settings {
  Real cell_size = 0;  // h, m: background grid cell, nodes at i·h (the origin is a node)
  ShapeFunctionKind shape_function = ShapeFunctionKind::ugimp;
  UpdateScheme scheme = UpdateScheme::usl;
  // Weight of FLIP in the particle velocity update, 0 = PIC, 1 = FLIP. 0.99 is usual:
  // almost no numerical damping, enough to stop ringing of the grid's null modes.
  Real flip_blend = 0.99;
  // The null-space filter on F, applied after every `null_space_filter_every`-th step
  // (docs/solver.md, "Null-space filter"); off by default.
  NullSpaceFilter null_space_filter = NullSpaceFilter::none;
  int null_space_filter_every = 1;  // steps, ≥ 1
  // DDMP's partition function α = peak · Π_axes [4 f (1 − f)]^exponent, f the point's
  // position in its cell (shape_ddmp.hpp): the default is Paper A's Eq. 5 in 3D; the two
  // numbers stay settings for studies.
  Real ddmp_alpha_peak = DdmpPartition{}.peak;          // in (0, 1]
  Real ddmp_alpha_exponent = DdmpPartition{}.exponent;  // > 0
  // DDMP's smoothed gradient on the grid (Paper A Eq. 4; ddmp_grid.hpp): nodal σ^d and L
  // instead of a dense 4×4×4 gradient per particle. Same results to round-off; false keeps
  // the per-particle evaluation (the reference in tests/mpm).
  bool ddmp_on_grid = true;
  // DDMP with sub-points (shape_ddmp_subpoints.hpp; Dhakal & Zhang 2016): the modified
  // gradient as the mean over 8 sub-points of each point's domain (on the grid only).
  bool ddmp_subpoints = false;
  // DDMP: a node with less mass than this fraction of ρ h³ (ρ the smallest density of a
  // deformable body) hands its mass, momentum and force on to its neighbours and reads its
  // velocity back from them (ddmp_grid.hpp, distribution coefficients). It also sets DDMP's
  // stable step: a node just above it takes smoothed force from a whole cell's stress on its
  // own small mass. DDMP's default cfl (default_cfl, mpm/names.cpp) is measured with this
  // value; a smaller fraction needs a smaller cfl (docs/tradeoff.md, "DDMP's small-mass
  // threshold sets its step"; 0.01 with cfl 0.3 until 2026-11-29).
  Real ddmp_small_mass_fraction = 0.015;  // in [0, 1)
  // DDMP: the stabilization of the smoothed gradient's null space (ddmp_stabilization.hpp),
  // β times the body's elastic moduli on the difference between the plain linear-MPM
  // gradient and Eq. 7's. 0: Paper A's DDMP as printed. DDMP on the grid without sub-points
  // only: the set-up refuses β > 0 — the default included — with ddmp_on_grid = false or
  // ddmp_subpoints (set 0 there; the scene reader does).
  Real ddmp_stabilization = 0.3;  // in [0, 1]
  // Fixed point bodies' nodes marked from a list made once, their points left out of the
  // transfers (fixed_body_nodes.hpp; bit-identical). false: scattered every step, as before
  // (the reference of test_mpm "Fixed bodies marked once*").
  bool mark_fixed_bodies_once = true;

  // Time step: automatic, dt = cfl · h / max_p(c_p + |v_p|), c_p the dilatational wave
  // speed of the particle's material (at its current J), re-evaluated every step.
  // 0.5 here (the tests' set-ups); scenes take default_cfl(shape) instead (uGIMP 0.4,
  // mpm/names.cpp), lowered from this value after thin-strut lattices failed at it.
  Real cfl = 0.5;             // dimensionless, in (0, 1]
  Real fixed_time_step = 0;   // s; > 0 replaces the automatic step (checked against the limit)
  Real max_time_step = 0;     // s; > 0 caps the automatic step (e.g. to sample outputs)

  // Mass scaling (Paper A Sec. 4: ρ = 6 ρ0 for quasi-static runs): every body's density is
  // multiplied by this factor; it lowers the wave speed and enlarges the stable step.
  Real mass_scaling = 1;      // dimensionless, ≥ 1 in practice

  Vec3 gravity = Vec3::Zero();  // m/s², acts on deformable bodies

  // Record layer (Paper A Sec. 5.1, GIMP runs): points carrying this tag in the point set
  // measure the load as F = A · σ̄_zz, σ̄_zz their volume-weighted mean vertical stress and
  // A = (their total initial volume) / (layer thickness). Empty name or no such tag: no
  // record force (reported as 0).
  std::string record_tag = "record";
  // Layer thickness, m. 0: the tagged points' initial extent along z plus one point spacing
  // (cell_size / ppc), i.e. the thickness of the layer of material those points represent.
  Real record_layer_thickness = 0;

  // Worker threads; 0 = all the machine offers. Results are identical for any count.
  int threads = 0;

  // Stability checks (issue: "Stability"). The run stops with NumericalError when the
  // kinetic energy exceeds runaway_energy_factor × (initial energy + external work so far),
  // beyond a floor of runaway_energy_floor (J) that ignores round-off at rest.
  Real runaway_energy_factor = 10;
  Real runaway_energy_floor = 1e-12;
  // ... and when the energy balance (StepDiagnostics::energy_error) is off by more than
  // energy_error_factor × the same energy put in, beyond the same floor: a step beyond its
  // stable size can ring from step to step with bounded kinetic energy while the transfer
  // books a loss many times the energy there is (B-splines at their former default CFL on a
  // stiff metal lattice: 600 J booked of 2.3 J of work; docs/tradeoff.md, "Time step").
  Real energy_error_factor = 10;
  // A particle whose volume ratio J = det F falls to this or below is inverted or crushed
  // beyond anything an elastic solid survives (1 % of its volume): the run stops.
  Real min_jacobian = 0.01;

  // Multi-field grid contact between bodies and point groups (field_contact.hpp); off: one field.
  FieldContactSettings field_contact;
};

// Throws InputError(where, field, ...) for a non-positive cell size, cfl outside (0, 1],
// flip_blend outside [0, 1], negative time steps or mass scaling ≤ 0.
void validate(const Settings& settings, const std::string& where);

}  // namespace latmpm::mpm
