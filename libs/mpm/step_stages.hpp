// The stages of a step as functions over the solver state (solver_state.hpp) and a
// StepContext: what the step needs besides the state (settings, the body table, the threads
// and their scratch, the domain). The three update schemes (Nairn 2003; Bardenhagen 2002)
// at the end of this file order the stages; the stages themselves live in transfer.hpp
// (particles ↔ grid, per bucket) and grid_update.cpp (nodes). Not installed for users:
// simulation.hpp is the interface. The domain (domain.hpp) is called where a run spread
// over processes needs it: migrate before a sort, halo exchange after every colour of a
// scatter, reductions of every sum the step makes over particles or nodes.
#pragma once
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>

#include "mpm/ddmp_grid.hpp"
#include "mpm/ddmp_small_mass.hpp"
#include "mpm/domain.hpp"
#include "mpm/field_contact.hpp"
#include "mpm/fixed_body_nodes.hpp"
#include "mpm/grid_update.hpp"
#include "mpm/null_space_filter.hpp"
#include "mpm/rigid_contact.hpp"
#include "mpm/settings.hpp"
#include "mpm/shape_functions.hpp"
#include "mpm/solver_state.hpp"
#include "mpm/transfer.hpp"

namespace latmpm::mpm {

struct BodySettings;

// The scatter and gather modes the three schemes combine.
using ScatterAll = ScatterMode<true, lane::momentum, true, true>;         // m, p, f, constraints
using ScatterMomentum = ScatterMode<true, lane::momentum, false, true>;    // m, p, constraints
using ScatterRemap = ScatterMode<false, lane::force, false, false>;       // p into lanes 4–6
using ScatterForce = ScatterMode<false, -1, true, false>;                 // f only
using GatherAll = GatherMode<true, true, lane::momentum>;
using GatherVelocity = GatherMode<true, false, -1>;
using GatherMotion = GatherMode<true, true, -1>;
using GatherStrain = GatherMode<false, false, lane::force>;
using GatherStrainAndPosition = GatherMode<false, true, lane::force>;

// The particle passes' sums (after the domain's reductions).
struct PassSums {
  Real kinetic = 0, strain = 0, dissipation = 0, gravity_power = 0;
  Real blend_dissipation = 0;  // of this step's velocity pass (BucketTally)
  // The grid's Σ ½ m_I |Δv_I|² before the velocity pass (node_increment_energy), and the
  // FLIP update's projection loss, twice what of it the pass did not give the points
  // (absorb_tallies; J, ≥ 0 where the points' weights are the ones that made the nodes' mass).
  Real node_increment_energy = 0;
  Real transfer_dissipation = 0;
  Real grid_contact_dissipation = 0;  // of this step's grid contact rule (ContactFields::dissipated)
  Real max_speed_sq = 0, max_wave_speed_sq = 0;
};

// Everything a step needs besides the state; rebuilt from the scene, never saved.
struct StepContext {
  StepContext(const Settings& s, const std::vector<BodySettings>& b, const std::vector<RigidBodySettings>& r)
      : settings(s), bodies(b), rigid_bodies(r), arena(s.threads > 0 ? s.threads : tbb::task_arena::automatic) {}

  const Settings& settings;
  const std::vector<BodySettings>& bodies;               // their names, for messages
  const std::vector<RigidBodySettings>& rigid_bodies;    // as added
  std::vector<BodyInfo> body_info;                       // per body: role, material, history columns
  Domain domain;  // other processes' parts (domain.hpp): nothing to do for one
  tbb::task_arena arena;
  tbb::enumerable_thread_specific<BucketBuffer> buffers;
  std::vector<BlockTable> tables;   // per bucket: its 4×4×4 grid blocks, from prepare_grid
  // Per bucket (bucket_columns.hpp): its cells' columns, then from prepare_grid its nodes'.
  std::vector<BucketColumns> columns;
  std::vector<BucketTally> tallies;
  std::vector<RunTally> run_tallies;
  std::vector<std::vector<uint32_t>> cpdi_wide;  // CPDI1: per bucket, its wide points of the last scatter
  PassSums sums;
  Reactions reactions;              // of the node update, per point body
  DdmpNodalValues ddmp_nodal;       // DDMP: σ^d, L and small-mass shares per node (ddmp_grid.hpp)
  FixedBodyNodes fixed_body_nodes;  // the marks of fixed bodies the step leaves out (fixed_body_nodes.hpp)
  Real ddmp_small_mass = -1;        // DDMP: below this a node's lanes go to its neighbours, kg (set on first use)
  // The most the penalty springs have held in this process's run, J: the energy checks count
  // it as put in, so that springs compressed at the start (points placed inside a body), once
  // released, do not count against the balance (Simulation::finish_step).
  Real peak_contact_energy = 0;
  // Penalty contact with rigid bodies (rigid_contact.hpp): off until a penalty body is added.
  bool penalty_contact = false;
  std::vector<ContactMaterial> contact_materials;  // per point body
  ContactForces contact;                           // of the current step, in particle order
  Real contact_rate_sq = 0;                        // largest κ_p/m_p, 1/s²
  // The grid's velocity fields (field_contact.hpp): one, or one per contact field; then
  // the field the scatter and gather passes take (−1: every point).
  GridFields grid_fields;
  int active_field = -1;
  // The carried speeds and energies must be taken from the particles again (at the start,
  // after mutable_particles() or a rigid body was added).
  bool refresh_needed = true;

  DdmpPartition ddmp_partition() const { return {settings.ddmp_alpha_peak, settings.ddmp_alpha_exponent}; }
};

// Calls f(Shape{}) with the policy the run uses: the settings' shape function, DDMP with
// its smoothed part on the grid (DdmpGridShape) unless Settings::ddmp_on_grid is off.
template <class F>
void with_solver_shape(const Settings& settings, F&& f) {
  with_shape_function(settings.shape_function, [&](auto shape) {
    if constexpr (std::is_same_v<decltype(shape), DdmpShape>)
      if (settings.ddmp_on_grid) return settings.ddmp_subpoints ? f(DdmpSubpointShape{}) : f(DdmpGridShape{});
    return f(shape);
  });
}
// DDMP on the grid: its smoothed force reaches one node beyond the particles' cells.
template <class Shape>
inline constexpr int grid_halo = Shape::smoothed_on_grid ? 1 : 0;

// --- Stages without a shape function (step_stages.cpp) ------------------------------------

// Node boxes from the particles' cells (after a sort or when positions were set).
void compute_boxes_from_positions(SolverState& s, StepContext& c);
// After a pass that moved the particles: the buckets' cell ranges for the next step.
void take_cell_ranges(SolverState& s, StepContext& c);
// The bucket tallies of a gather summed (in bucket order) and reduced over the domain;
// throws NumericalError naming the first faulty particle.
void absorb_tallies(SolverState& s, StepContext& c, bool velocity, bool position, bool gradient);
// The node update (grid_update.hpp) and its reactions, then every boundary's constraint.
void update_nodes(SolverState& s, StepContext& c, Real dt);
// Σ ½ m_I |Δv_I|² over the grid's nodes after the node update (J), in block order.
Real node_increment_energy(SolverState& s, StepContext& c);
// After the node update: every boundary constrains its nodes and keeps its reaction.
void constrain_boundaries(SolverState& s, StepContext& c, Real dt);
// The boundaries' velocities on the field in lanes [lane, lane + 3), without reactions.
void impose_boundaries(SolverState& s, StepContext& c, int lane);
BoundaryPass boundary_pass(SolverState& s, StepContext& c, Real dt);
// After a penalty body was added: contact history for every point, the default stiffness
// per body and the contact's bound on the time step.
void enable_penalty_contact(SolverState& s, StepContext& c);
// The penalty contact forces at the start of the step (positions x^n, bodies at X^n).
void update_contact_forces(SolverState& s, StepContext& c);
// ε ρ h³, ρ the smallest density of a deformable body's points (Settings::ddmp_small_mass_fraction).
Real ddmp_small_mass(const SolverState& s, StepContext& c);
// Centre of mass of body `body` from the last position pass's run tallies, m.
Vec3 centre_of_mass(const SolverState& s, const StepContext& c, size_t body);
// ψ of deformable particle p (J/m³ of reference volume), with its history if its model has one.
Real energy_density(const SolverState& s, const StepContext& c, size_t p);
// Sets the history columns named (all that are derived when `names` is empty) of every
// deformable point from its deformation and stress (material_history.hpp, derives_history):
// at the start of a run and for a checkpoint without those columns.
void derive_history_from_state(SolverState& s, const StepContext& c, const std::vector<std::string>& names);
// "the fastest particle: ID of body 'NAME' at (x, y, z) m, v m/s" (deformable bodies, the
// whole domain's: the same words on every process, collective), for messages that stop a run
// whose trouble has no one particle of its own (the energy checks).
std::string fastest_particle(const SolverState& s, const StepContext& c);
// The carried state with speeds, energy and body centres from the particles as they are now:
// at the start, and after a caller changed them through mutable_particles() before the
// first step. refresh_carried keeps it (StepContext::refresh_needed).
CarriedState carried_from_particles(const SolverState& s, const StepContext& c);
void refresh_carried(SolverState& s, StepContext& c);
// cfl · h/(c + |v|); with penalty contact cfl · 2/√(ω² + κ/m) (rigid_contact.hpp); from
// the particles as they are now when the carried state needs a refresh.
Real stable_time_step(const SolverState& s, const StepContext& c);

// --- The grid and the transfers -------------------------------------------------------

// --- CPDI1 domains wider than a bucket's stencil box (shape_cpdi.hpp) ------------------

// The most cells a CPDI1 domain may span along an axis before the run stops (a run-away F).
inline constexpr int max_cpdi_domain_cells = 31;

// Adds the grid blocks of every wide domain's vertex nodes (one node of margin: in USF the
// domain deforms between this and the force scatter) to `keys`.
inline void add_wide_cpdi_blocks(const SolverState& s, const StepContext& c, std::vector<uint64_t>& keys) {
  constexpr int bw = SparseGrid::block_width;
  const Real h = c.settings.cell_size;
  const Particles& ps = s.particles;
  for (size_t p = 0; p < ps.size(); ++p) {
    int lo[3], hi[3];
    cpdi_vertex_cell_range(ps, p, h, lo, hi);
    const auto cell = cell_of(ps.position[p], 1 / h);
    bool wide = false;
    for (int a = 0; a < 3; ++a) wide = wide || cpdi_vertex_outside_box(lo[a], cell[a]) || cpdi_vertex_outside_box(hi[a], cell[a]);
    if (!wide) continue;  // (a non-finite vertex is left to its stencil, which reports it)
    // A domain stretched over many cells is a run-away F, not a CPDI1 domain (paper B's
    // coarsest B1 spans 2.5 cells): stop before its bounding box activates a huge grid.
    for (int a = 0; a < 3; ++a)
      if (hi[a] - lo[a] > max_cpdi_domain_cells || std::abs(lo[a]) > max_cell_coord || std::abs(hi[a]) > max_cell_coord)
        throw NumericalError("CPDI domain of point " + std::to_string(ps.id[p]) + " at (" +
                             std::to_string(ps.position[p][0]) + ", " + std::to_string(ps.position[p][1]) + ", " +
                             std::to_string(ps.position[p][2]) + ") m spans " + std::to_string(hi[a] - lo[a] + 1) +
                             " cells along axis " + std::to_string(a) + " (at most " +
                             std::to_string(max_cpdi_domain_cells + 1) + "): its deformation has run away");
    for (int i = floor_div(lo[0] - 1, bw); i <= floor_div(hi[0] + 2, bw); ++i)
      for (int j = floor_div(lo[1] - 1, bw); j <= floor_div(hi[1] + 2, bw); ++j)
        for (int k = floor_div(lo[2] - 1, bw); k <= floor_div(hi[2] + 2, bw); ++k)
          keys.push_back(SparseGrid::block_key(i, j, k));
  }
}

// After the buckets: the wide points' lanes onto the grid, vertex by vertex (Eq. 7), in
// bucket and particle order (the same sums for any thread count).
template <class Mode>
void scatter_wide_cpdi_points(SolverState& s, StepContext& c) {
  const Real h = c.settings.cell_size;
  for (const auto& points : c.cpdi_wide)
    for (uint32_t p : points) {
      if (c.domain.process_count() > 1)
        throw NumericalError("CPDI domain of point " + std::to_string(s.particles.id[p]) +
                             " reaches more than one cell from its centre, which runs on one process only");
      const CpdiBoxStencil st = make_cpdi_box_stencil(s.particles, p, h);
      const ScatterLanes l = scatter_lanes<Mode>(s.particles, p);
      for_each_cpdi_vertex_node(st, [&](int i, int j, int k, Real w, Real gx, Real gy, Real gz) {
        Real* node = s.grid.node(i, j, k);
        if (!node)
          throw NumericalError("CPDI domain of point " + std::to_string(s.particles.id[p]) +
                               " reaches a grid node outside the active grid");
        NodeLanes add = w * l.a;
        if constexpr (Mode::force) add += gx * l.fx + gy * l.fy + gz * l.fz;
        store_lanes(node, load_lanes(node) + add);
      });
    }
}

template <class Shape>
void prepare_grid(SolverState& s, StepContext& c) {
  // A sort on any process is a sort on all: the buckets stay those of one process.
  const bool columns_stale = c.columns.size() != s.buckets.buckets().size();
  s.needs_sort = c.domain.reduce_max(s.needs_sort || columns_stale ? 1 : 0) > 0;
  if (s.needs_sort) {
    c.domain.migrate_particles(s.particles, c.settings.cell_size);
    s.buckets.sort(s.particles, c.settings.cell_size);
    compute_boxes_from_positions(s, c);
    s.needs_sort = false;
  }
  // Bucket boxes hold cell ranges until here; widen them by the stencil's reach.
  auto& list = s.buckets.buckets();
  for (Bucket& b : list)
    for (int a = 0; a < 3; ++a) {
      b.box_lo[a] += Shape::reach_below;
      b.box_hi[a] += Shape::reach_above;
    }
  tbb::parallel_for(size_t(0), list.size(), [&](size_t bi) {
    c.columns[bi] = stencil_columns<Shape::reach_below, Shape::reach_above>(c.columns[bi]);
  });
  std::vector<uint64_t> keys;
  for (size_t bi = 0; bi < list.size(); ++bi) add_column_blocks<grid_halo<Shape>>(list[bi], c.columns[bi], keys);
  if constexpr (Shape::uses_domain_vertices) add_wide_cpdi_blocks(s, c, keys);
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  s.grid.set_active_blocks(keys);
  c.domain.share_grid(s.grid, s.buckets);
  c.tables.resize(list.size());
  for (size_t bi = 0; bi < list.size(); ++bi) {
    const Bucket& b = list[bi];
    int first[3];
    for (int a = 0; a < 3; ++a) first[a] = first_table_block(b.coord[a]);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k)
          c.tables[bi][(i * 4 + j) * 4 + k] = s.grid.find(first[0] + i, first[1] + j, first[2] + k);
  }
  if constexpr (Shape::smoothed_gradient) prepare_ddmp_nodal_values(s.grid, c.ddmp_nodal);
  if constexpr (Shape::smoothed_on_grid)
    fill_ddmp_alpha(s.particles.position, c.settings.cell_size, c.ddmp_partition(), c.ddmp_nodal);
  clear_grid(s.grid);
  mark_fixed_bodies<Shape>(c.fixed_body_nodes, s.particles, c.body_info, c.settings.cell_size, s.grid);
  s.grid_holds_velocity = false;
  c.tallies.assign(list.size(), BucketTally{});
  c.run_tallies.assign(s.buckets.runs().size(), RunTally{});
  if constexpr (Shape::uses_domain_vertices) c.cpdi_wide.resize(list.size());
}

template <class Shape, class Mode>
void scatter(SolverState& s, StepContext& c) {
  const auto& list = s.buckets.buckets();
  constexpr bool nodal_stress = Mode::force && Shape::smoothed_on_grid;
  if constexpr (nodal_stress) clear_ddmp_nodal_values(c.ddmp_nodal);
  DdmpAlphaCache alpha_cache;
  if constexpr (Shape::smoothed_on_grid) alpha_cache = ddmp_alpha_of_step(c.ddmp_nodal);
  for (int ci = 0; ci < 8; ++ci) {
    const auto& colour = s.buckets.colours()[size_t(ci)];
    // Buckets of one colour are two buckets apart: their boxes never overlap.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, colour.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      BucketBuffer& buffer = c.buffers.local();
      for (size_t k = r.begin(); k < r.end(); ++k) {
        const Bucket& b = list[colour[k]];
        if (c.active_field >= 0 && !bucket_has_field(b, s.buckets.runs(), s.particles, c.active_field)) continue;
        buffer.field = c.active_field;
        buffer.attach(b);
        buffer.ddmp_alpha = c.ddmp_partition();
        buffer.ddmp_alpha_cache = alpha_cache;
        clear_box(b, c.columns[colour[k]], buffer);
        if constexpr (nodal_stress) clear_ddmp_box(b, c.columns[colour[k]], c.tables[colour[k]], buffer);
        scatter_bucket<Shape, Mode>(b, &s.buckets.runs()[b.run_begin], s.particles, c.body_info.data(),
                                    c.settings.cell_size, buffer);
        if constexpr (Shape::uses_domain_vertices) c.cpdi_wide[colour[k]].swap(buffer.wide_points);
        add_box_to_grid(b, c.columns[colour[k]], c.tables[colour[k]], s.grid, buffer);
        if constexpr (nodal_stress) add_ddmp_box_to_grid(b, c.columns[colour[k]], c.tables[colour[k]], buffer, c.ddmp_nodal);
      }
    });
    c.domain.exchange_halo(s.grid, ci);  // shared nodes as one process has them after this colour
  }
  if constexpr (Shape::uses_domain_vertices) scatter_wide_cpdi_points<Mode>(s, c);
  if constexpr (nodal_stress) {  // Paper A Eq. 4: the smoothed part of the force on the grid
    add_ddmp_smoothed_force(s.grid, c.ddmp_nodal, c.settings.cell_size);
  }
}

// The gather's particle passes, their bucket tallies into `tallies` (one per bucket).
template <class Shape, class Mode>
void gather_buckets(SolverState& s, StepContext& c, Real dt, std::vector<BucketTally>& tallies) {
  const auto& list = s.buckets.buckets();
  const Settings& st = c.settings;
  const GatherParameters parameters{st.cell_size, dt, st.flip_blend, st.gravity, st.min_jacobian};
  constexpr bool nodal_gradient = Mode::gradient_lane >= 0 && Shape::smoothed_on_grid;
  if constexpr (nodal_gradient) ddmp_nodal_velocity_gradient(s.grid, Mode::gradient_lane, st.cell_size, c.ddmp_nodal);
  DdmpAlphaCache alpha_cache;
  if constexpr (Shape::smoothed_on_grid) alpha_cache = ddmp_alpha_of_step(c.ddmp_nodal);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, list.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
    BucketBuffer& buffer = c.buffers.local();
    buffer.grid = &s.grid;  // wide CPDI1 stencils read their nodes from it
    for (size_t bi = r.begin(); bi < r.end(); ++bi) {
      const Bucket& b = list[bi];
      if (c.active_field >= 0 && !bucket_has_field(b, s.buckets.runs(), s.particles, c.active_field)) continue;
      buffer.field = c.active_field;
      buffer.attach(b);
      buffer.ddmp_alpha = c.ddmp_partition();
      buffer.ddmp_alpha_cache = alpha_cache;
      copy_box_from_grid(b, c.columns[bi], c.tables[bi], s.grid, buffer);
      if constexpr (nodal_gradient) copy_ddmp_box_from_grid(b, c.columns[bi], c.tables[bi], c.ddmp_nodal, buffer);
      gather_bucket<Shape, Mode>(b, &s.buckets.runs()[b.run_begin], s.particles, c.body_info.data(), parameters,
                                 buffer, tallies[bi], &c.run_tallies[b.run_begin]);
    }
  });
}

template <class Shape, class Mode>
void gather(SolverState& s, StepContext& c, Real dt) {
  // The projection's loss is booked for USL only (absorb_tallies): the node sum is needed there.
  if constexpr (Mode::velocity && Mode::gradient_lane >= 0) c.sums.node_increment_energy = node_increment_energy(s, c);
  gather_buckets<Shape, Mode>(s, c, dt, c.tallies);
  absorb_tallies(s, c, Mode::velocity, Mode::position, Mode::gradient_lane >= 0);
}

// --- DDMP's small-mass nodes (ddmp_grid.hpp) --------------------------------------------

// After a scatter: small-mass nodes hand lanes [first, first + count) on to their
// neighbours (`find`: decide which nodes those are, from the mass just mapped).
template <class Shape, int First, int Count>
void ddmp_hand_on(SolverState& s, StepContext& c, bool find) {
  if constexpr (Shape::smoothed_gradient) {
    if (find) find_ddmp_small_mass_nodes(s.grid, ddmp_small_mass(s, c), c.ddmp_nodal);
    move_ddmp_small_mass_lanes<First, Count>(s.grid, c.ddmp_nodal);
  }
}
// After the nodal velocities: the small-mass nodes' lanes read back from their neighbours.
template <class Shape, int First, int Count>
void ddmp_read_back(SolverState& s, StepContext& c) {
  if constexpr (Shape::smoothed_gradient) spread_ddmp_small_mass_lanes<First, Count>(s.grid, c.ddmp_nodal);
}

// --- The contact stage (rigid_contact.hpp) ----------------------------------------------

// The contact forces at the start of the step into the force lanes, f_i += S_ip f_p, point
// by point in order (deterministic), with the weights S_ip that move the point (its G2P
// interpolation), so that the grid's power Σ f_i·v_i is the points' Σ f_p·v_p. DDMP's
// weights are the linear ones (shape_ddmp.hpp); CPDI1 points take their domain's averaged
// functions (Eq. 7). Paper B handles contact at the material point (Sec. 3.4): its position
// decides the contact, its weights spread the force. (Spread with the linear stencil of the
// material point instead, the force reached nodes that hold little of a CPDI point's mass,
// whose kicks put twice the contact's work into the grid: +3 % in the SHPB's energy
// balance, docs/paper-b.md.) contact_spread gives one point's weights; add_contact_forces
// adds them.
// Point p's spreading weights as a record: its force, its terms, the weights S_ip of the
// nodes base + (i, j, k) (zero: not touched; nodes = 0: a wide CPDI1 domain, spread vertex
// by vertex from the local particle, one process only).
template <class Shape>
ContactSpread contact_spread(const SolverState& s, const StepContext& c, size_t t, Real h) {
  const uint32_t p = c.contact.touching[t];
  ContactSpread out;
  out.index = p;
  out.body = s.particles.contact_body[p];
  for (int a = 0; a < 3; ++a) out.force[a] = c.contact.force[p][a];
  out.spring_energy = c.contact.touching_spring[t];
  out.friction_work = c.contact.touching_friction[t];
  if constexpr (Shape::uses_domain_vertices) {
    constexpr int N = CpdiBoxStencil::n;
    static_assert(N <= ContactSpread::max_nodes_per_axis);
    const CpdiBoxStencil st = make_cpdi_box_stencil(s.particles, p, h);
    if (st.wide) return out;  // nodes = 0: spread vertex by vertex (add_contact_forces)
    out.nodes = N;
    for (int a = 0; a < 3; ++a) out.base[a] = st.base[a];
    for (int i = 0; i < N * N * N; ++i) out.weight[i] = st.w[i];
  } else {
    using Weights = std::conditional_t<Shape::smoothed_gradient, LinearShape, Shape>;
    constexpr int N = Weights::nodes_per_axis;
    static_assert(N <= ContactSpread::max_nodes_per_axis);
    const auto st = make_stencil<Weights>(s.particles.position[p], stencil_half_size<Weights>(s.particles, p, h), 1 / h);
    out.nodes = N;
    for (int a = 0; a < 3; ++a) out.base[a] = st.base[a];
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        for (int k = 0; k < N; ++k) out.weight[(i * N + j) * N + k] = st.w[i][0] * st.w[j][1] * st.w[k][2];
  }
  return out;
}

template <class Shape>
void add_contact_forces(SolverState& s, StepContext& c) {
  if (!c.penalty_contact) return;
  update_contact_forces(s, c);
  const Real h = c.settings.cell_size;
  std::vector<ContactSpread> spreads(c.contact.touching.size());
  for (size_t t = 0; t < spreads.size(); ++t) spreads[t] = contact_spread<Shape>(s, c, t, h);
  // Several processes: every touching point's record, in the one-process order; each
  // process adds them to the nodes it holds (whole after the scatter's halo exchange) and
  // forms the reaction sums in that order (contact_spread.hpp).
  if (c.domain.process_count() > 1) {
    spreads = c.domain.contact_spreads_in_order(std::move(spreads), s.buckets);
    contact_sums_in_order(spreads, c.rigid_bodies.size(), c.contact);
  }
  for (const ContactSpread& sp : spreads) {
    if constexpr (Shape::uses_domain_vertices)
      if (sp.nodes == 0) {  // a wide CPDI1 domain: its vertices' own cells (sp.index is local)
        if (c.domain.process_count() > 1)
          throw NumericalError("a CPDI domain touching a penalty body reaches more than one cell from its centre, "
                               "which runs on one process only");
        const CpdiBoxStencil st = make_cpdi_box_stencil(s.particles, uint32_t(sp.index), h);
        for_each_cpdi_vertex_node(st, [&](int i, int j, int k, Real w, Real, Real, Real) {
          if (!(w > 0)) return;
          Real* lanes = s.grid.node(i, j, k);
          if (!lanes)
            throw NumericalError("CPDI domain of point " + std::to_string(s.particles.id[sp.index]) +
                                 " spreads its contact force to a grid node outside the active grid");
          for (int a = 0; a < 3; ++a) lanes[lane::force + a] += w * sp.force[a];
        });
        continue;
      }
    const int N = sp.nodes;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        for (int k = 0; k < N; ++k)
          if (const Real w = sp.weight[(i * N + j) * N + k]; w > 0) {
            Real* lanes = s.grid.node(sp.base[0] + i, sp.base[1] + j, sp.base[2] + k);
            if (lanes) {  // held here
              for (int a = 0; a < 3; ++a) lanes[lane::force + a] += w * sp.force[a];
            } else if (c.domain.process_count() == 1) {  // one process holds every node its points reach
              throw NumericalError("the contact force of point " + std::to_string(s.particles.id[sp.index]) +
                                   " reaches a grid node outside the active grid");
            }
          }
  }
}

// --- Schemes (Nairn 2003; Bardenhagen 2002) -------------------------------------------

// The first half of USL and MUSL: mass, momentum and force to the grid, the nodes advanced.
template <class Shape>
void scatter_all_and_update_nodes(SolverState& s, StepContext& c, Real dt) {
  prepare_grid<Shape>(s, c);
  scatter<Shape, ScatterAll>(s, c);
  add_contact_forces<Shape>(s, c);
  ddmp_hand_on<Shape, lane::mass, 7>(s, c, true);
  update_nodes(s, c, dt);
  ddmp_read_back<Shape, lane::momentum, 6>(s, c);
}

template <class Shape>
void step_usl(SolverState& s, StepContext& c, Real dt) {
  scatter_all_and_update_nodes<Shape>(s, c, dt);
  gather<Shape, GatherAll>(s, c, dt);
}

template <class Shape>
void step_musl(SolverState& s, StepContext& c, Real dt) {
  scatter_all_and_update_nodes<Shape>(s, c, dt);
  gather<Shape, GatherVelocity>(s, c, dt);
  // Map the updated particle momentum back (lanes 4–6) and take L from that velocity.
  clear_grid_lanes(s.grid, lane::force, 3);
  scatter<Shape, ScatterRemap>(s, c);
  ddmp_hand_on<Shape, lane::force, 3>(s, c, false);
  grid_velocity_from_momentum(s.grid, lane::force, lane::force, c.body_info);
  ddmp_read_back<Shape, lane::force, 3>(s, c);
  impose_boundaries(s, c, lane::force);
  gather<Shape, GatherStrainAndPosition>(s, c, dt);
}

template <class Shape>
void step_usf(SolverState& s, StepContext& c, Real dt) {
  prepare_grid<Shape>(s, c);
  scatter<Shape, ScatterMomentum>(s, c);
  ddmp_hand_on<Shape, lane::mass, 4>(s, c, true);
  // Stress first, from the velocity at the start of the step (lanes 4–6).
  grid_velocity_from_momentum(s.grid, lane::momentum, lane::force, c.body_info);
  ddmp_read_back<Shape, lane::force, 3>(s, c);
  impose_boundaries(s, c, lane::force);
  gather<Shape, GatherStrain>(s, c, dt);
  clear_grid_lanes(s.grid, lane::force, 3);
  scatter<Shape, ScatterForce>(s, c);
  add_contact_forces<Shape>(s, c);
  ddmp_hand_on<Shape, lane::force, 3>(s, c, false);
  update_nodes(s, c, dt);
  ddmp_read_back<Shape, lane::momentum, 6>(s, c);
  gather<Shape, GatherMotion>(s, c, dt);
}

// One step of the settings' scheme with the settings' shape function, on the context's threads;
// with grid contact, its step (field_contact.hpp); then the null-space filter where the
// settings ask for it (null_space_filter.hpp).
inline void step_scheme(SolverState& s, StepContext& c, Real dt) {
  c.arena.execute([&] {
    if (auto* fields = std::get_if<ContactFields>(&c.grid_fields)) {
      step_with_field_contact(s, c, *fields, dt);
    } else {
      with_solver_shape(c.settings, [&](auto shape) {
        using Shape = decltype(shape);
        switch (c.settings.scheme) {
          case UpdateScheme::usl: step_usl<Shape>(s, c, dt); break;
          case UpdateScheme::usf: step_usf<Shape>(s, c, dt); break;
          case UpdateScheme::musl: step_musl<Shape>(s, c, dt); break;
        }
      });
    }
    null_space_filter_stage(s, c);
  });
}

}  // namespace latmpm::mpm
