// Boundaries: the one closed set of everything that constrains or pushes the model from
// outside its deformable material — point-defined fixed and driven bodies and held points,
// geometric rigid bodies coupled no-slip through the grid, and rigid bodies in penalty
// contact with friction. Every kind has the same hooks, and the step, the energy sums, the
// series and the checkpoint loop over boundaries instead of branching per mechanism
// (docs/architecture.md, "Adding a boundary"):
//
//   mark        which grid nodes it takes. Point-defined kinds mark in P2G: the nodes their
//               points' stencils reach get the body's marker in the constraint lane
//               (transfer.hpp, the stencils are only there); geometric kinds claim the nodes
//               their support overlaps in `constrain` (marker −(index + 1): first wins).
//   contact     forces on material points before the grid update (penalty contact: the
//               contact stage, rigid_contact.hpp, run once for all penalty boundaries since
//               a point keeps one contact at a time).
//   constrain   after the grid update: imposes its velocity on its nodes and keeps the
//               reaction, the force it applies to the model this step (N).
//   impose      the same velocity constraint on a velocity field without reactions (MUSL's
//               remapped velocity, USF's start-of-step velocity).
//   advance     after the step: its power on the model, its motion, its energy.
//   save/load   its state in a checkpoint group of its own.
//   report      what the series shows of it (role, displacement, reaction, velocity).
//
// Order: point-defined boundaries in body order, then geometric ones in scene order; all
// sums run in that order, so results do not depend on how the set is held.
//
// Body-to-body contact (strut against strut, docs/architecture.md "Contact between bodies")
// will not be a boundary: it needs a velocity field per body on the shared nodes (lanes per
// field, Bardenhagen 2001), with the contact law acting between fields in the grid update.
// It enters as a grid with several fields per node and a contact stage beside the penalty
// one; boundaries then constrain the field of the body they touch.
#pragma once
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "mpm/body.hpp"
#include "mpm/domain.hpp"
#include "mpm/real.hpp"
#include "mpm/rigid_body.hpp"

namespace latmpm::mpm {

class SparseGrid;
class CheckpointWriter;
class CheckpointReader;
struct Reactions;
struct ContactForces;

// What the hooks see of a step.
struct BoundaryPass {
  SparseGrid& grid;
  Real cell_size;  // m
  Real dt;         // s
  Vec3 gravity;    // m/s²
  const Reactions* node_reactions = nullptr;  // the node update's sums per point body (grid_update.hpp)
  const ContactForces* contact = nullptr;     // the contact stage's forces (rigid_contact.hpp)
  const Domain* domain = nullptr;             // sums over every process's grid blocks (domain.hpp)
};

// The energy bookkeeping the boundaries feed after a step (J, W).
struct BoundaryLedger {
  Real external_power = 0;    // W: work rate of every boundary on the model
  Real constraint_power = 0;  // W: of the driven point bodies (StepDiagnostics::constraint_work)
  Real prescribed_work = 0;   // J: this step's work of rigid bodies of prescribed motion
  Real energy = 0;            // J: kinetic + potential energy of free rigid bodies
  Real contact_energy = 0;    // J: held in the penalty bodies' contact springs now
  Real friction_dissipation = 0;  // J: dissipated by the penalty bodies' friction since the start
  Real max_speed = 0;         // m/s: fastest boundary (enters the stable time step)
};

// How the series reads a boundary.
enum class BoundaryRole { fixed, driven, free, held };
struct BoundaryReport {
  std::string name;
  BoundaryRole role = BoundaryRole::fixed;
  Vec3 displacement = Vec3::Zero();  // m
  Vec3 reaction = Vec3::Zero();      // N, force on the model in the last step
  Vec3 velocity = Vec3::Zero();      // m/s
  Real kinetic_energy = 0, potential_energy = 0;  // J (free rigid bodies)
};

// A fixed or driven point body, or the held points of a deformable body (body.hpp).
struct PointBoundary {
  size_t body = 0;  // index in Simulation::bodies()
  std::string name;
  BodyRole role = BodyRole::fixed;
  Vec3 velocity = Vec3::Zero();      // m/s, driven
  Vec3 displacement = Vec3::Zero();  // m, ∫ v dt (driven)
  Vec3 reaction = Vec3::Zero();
  Real power = 0;  // W, this step's r·v at the prescribed velocity

  void constrain(BoundaryPass& pass);
  void impose(BoundaryPass&, int) {}  // the node pass imposes point constraints (grid_update.hpp)
  void advance(const BoundaryPass& pass, BoundaryLedger& ledger);
  void save(CheckpointWriter& out) const;
  void load(const CheckpointReader& in);
  BoundaryReport report() const;
};

// A geometric rigid body coupled no-slip through the grid (rigid_body.hpp).
struct RigidBoundary {
  size_t index = 0;  // index in Simulation::rigid_bodies()
  RigidBodySettings settings;
  RigidBodyState state;
  Vec3 reaction = Vec3::Zero();

  void constrain(BoundaryPass& pass);
  void impose(BoundaryPass& pass, int lane);
  void advance(const BoundaryPass& pass, BoundaryLedger& ledger);
  void save(CheckpointWriter& out) const;
  void load(const CheckpointReader& in);
  BoundaryReport report() const;
};

// A geometric rigid body in penalty contact with friction (rigid_contact.hpp): its nodes stay
// free; the contact stage pushes the points it touches. Its work is its own power on its
// springs, f·V (the anchors move with it); of that the springs hold ½|f|²/κ and friction
// dissipates the anchors' slip, both reported beside the work.
struct PenaltyBoundary : RigidBoundary {
  Real spring_energy = 0;         // J, in its springs at the last contact pass
  Real friction_dissipation = 0;  // J, since the start

  void constrain(BoundaryPass& pass);
  void impose(BoundaryPass&, int) {}
  void advance(const BoundaryPass& pass, BoundaryLedger& ledger);
  void save(CheckpointWriter& out) const;
  void load(const CheckpointReader& in);
};

// Whether T has every hook of a boundary (a new alternative must, before it joins the set).
template <class T, class = void>
struct has_boundary_hooks : std::false_type {};
template <class T>
struct has_boundary_hooks<
    T, std::void_t<decltype(std::declval<T&>().constrain(std::declval<BoundaryPass&>())),
                   decltype(std::declval<T&>().impose(std::declval<BoundaryPass&>(), 0)),
                   decltype(std::declval<T&>().advance(std::declval<const BoundaryPass&>(), std::declval<BoundaryLedger&>())),
                   decltype(std::declval<const T&>().save(std::declval<CheckpointWriter&>())),
                   decltype(std::declval<T&>().load(std::declval<const CheckpointReader&>())),
                   decltype(BoundaryReport(std::declval<const T&>().report()))>> : std::true_type {};

// The closed set. A new kind (a rigid plate without particles, paper B's attachment-point
// friction contact) is one struct with the hooks above and one alternative here.
using Boundary = std::variant<PointBoundary, RigidBoundary, PenaltyBoundary>;
static_assert(has_boundary_hooks<PointBoundary>::value && has_boundary_hooks<RigidBoundary>::value &&
              has_boundary_hooks<PenaltyBoundary>::value);

// The rigid body a geometric boundary is (nullptr for point-defined ones).
const RigidBoundary* as_rigid(const Boundary& boundary);
RigidBoundary* as_rigid(Boundary& boundary);
std::string checkpoint_name(const Boundary& boundary);

}  // namespace latmpm::mpm
