// Multi-field grid contact (Bardenhagen et al. 2000, 2001; Huang et al. 2011): every point
// belongs to a velocity field, every field has its own mass, momentum and force on the
// grid nodes, and a contact rule between the fields on a node where several meet: normals
// from the fields' mass gradients, no interpenetration (the approaching normal velocity
// taken out), Coulomb friction on the tangential part. Without it all points share one
// field, and bodies — or struts of one body — that touch move as one and stick, also in
// tension (paper A Sec. 6 names strut-strut contact as future work). docs/contact.md.
//
// Fields: one per deformable body, and inside a body one per point group (a point tag,
// FieldContactSettings::groups): a strut or a set of struts. A group is bonded to the rest
// of its body (its untagged points, the joints) — on a node where bonded fields meet they
// move as one field (Homel & Herbold 2017's joint zone) — and in contact with every other
// field. The step (field_contact_step.cpp) scatters each field into its own lanes, sums
// them into the grid, runs the ordinary node update on the sum (centre-of-mass velocity,
// boundaries, reactions), then corrects each field's velocity on contact nodes here.
#pragma once
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "mpm/field_contact_settings.hpp"
#include "mpm/particle_buckets.hpp"
#include "mpm/sparse_grid.hpp"
#include "mpm/transfer.hpp"

namespace latmpm {
struct PointSet;
}

namespace latmpm::mpm {

struct BodySettings;
struct SolverState;
struct StepContext;

// The fields' limits: a field index is a byte, bonds a 32-bit mask, and the bucket sort
// key's body bits hold body · 32 + field (particle_buckets.cpp).
inline constexpr int max_contact_fields = 32;
inline constexpr int max_contact_bodies = 256;

// One grid holds every point: the single-field solver.
struct OneField {};

// The per-field state of a run with grid contact; rebuilt from the scene, never saved
// (the points' fields are a particle field, Particles::contact_field).
struct ContactFields {
  int count = 0;
  Real friction = 0;
  std::vector<uint32_t> bonded;       // per field: mask of the fields it moves with where they meet (itself included)
  std::vector<std::string> names;     // per field: "<body>" or "<body>/<group tag>", for messages
  std::vector<Real> density;          // per field: its body's density (mass scaled), kg/m³; rigid: 0
  Real fill = 0.9;                    // FieldContactSettings::fill
  std::vector<NodeStorage> lanes;     // per field: node lanes laid out like SparseGrid's
  std::vector<BucketTally> pass_tallies;  // one field's gather, merged into StepContext::tallies
  // Diagnostics of the last step's contact rule.
  size_t contact_nodes = 0;           // nodes where fields that are not bonded met and approached
  Real dissipated = 0;                // J, kinetic energy the rule took out this step (≥ 0)
};

// The grid's velocity fields, a closed set (docs/architecture.md, "Contact between bodies").
using GridFields = std::variant<OneField, ContactFields>;

// The fields of a run: field indices of the points (Particles::contact_field, in point
// order) and the fields' bonds and names. Throws InputError naming `where` and the
// contact key for a group tag no deformable point carries, too many fields or bodies.
ContactFields make_contact_fields(const FieldContactSettings& settings, Real mass_scaling, const PointSet& points,
                                  const std::vector<BodySettings>& bodies, std::vector<uint8_t>& point_field,
                                  const std::string& where);

// True if bucket b holds a run of field `field` (rigid points are field 0).
inline bool bucket_has_field(const Bucket& b, const std::vector<BodyRun>& runs, const Particles& ps, int field) {
  for (uint32_t r = b.run_begin; r < b.run_end; ++r)
    if (ps.contact_field[runs[r].begin] == field) return true;
  return false;
}

// A tally with nothing in it, and one field's tally merged into a bucket's.
BucketTally empty_tally();
void merge_tally(BucketTally& into, const BucketTally& from);

// Every field's lanes sized like the grid's and zeroed (after prepare_grid).
void clear_field_lanes(const SparseGrid& grid, ContactFields& fields);
// The grid's lanes as the sum of the fields' (mass, momentum, force; constraint: the largest
// mark) — what a single-field scatter would have put there.
void sum_fields_into_grid(SparseGrid& grid, const ContactFields& fields);
// After the node update on the summed grid (velocity v and change Δv of the centre of
// mass, boundaries applied): each field's lanes become its velocity and change. Where one
// field has mass, or the node is constrained, or the fields present are bonded, a field
// takes the grid's; elsewhere the contact rule (Bardenhagen et al. 2001 Eq. 13–21):
//   δ_K = v*_K − v*_cm (free velocities of the field cluster K and of the centre of mass),
//   n_K = (∇m_rest − ∇m_K)/|…| (from K toward the others; nodal mass by central differences),
//   if δ_K·n_K > 0 (approaching): v_K = v_cm + δ_K − (δ_K·n_K) n_K − min(μ δ_K·n_K, |δ_t|) t̂,
//   else v_K = v_cm + δ_K (free; they separate).
void apply_field_contact(SparseGrid& grid, ContactFields& fields, Real dt, const Vec3& gravity, Real h);

// One USL step with the fields (field_contact_step.cpp): each field scattered into its
// lanes, the sum updated like one field, the contact rule, each field gathered. Shapes with
// a smoothed gradient (DDMP) or domain vertices (CPDI1) are refused (validate).
void step_with_field_contact(SolverState& s, StepContext& c, ContactFields& fields, Real dt);

}  // namespace latmpm::mpm
