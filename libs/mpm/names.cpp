// Scene names of the solver's enumerations, both ways: one table per choice, which the scene
// reader, its error messages and `latmpm-solve --list` all read. A new shape function (with
// its default CFL), scheme, material model, body role or rigid-body shape, motion or
// coupling is one row here.
#include <array>
#include <tuple>
#include <utility>

#include "core/errors.hpp"
#include "mpm/body.hpp"
#include "mpm/material.hpp"
#include "mpm/name_table.hpp"
#include "mpm/rigid_body.hpp"
#include "mpm/settings.hpp"
#include "mpm/shape_function_kind.hpp"

namespace latmpm::mpm {

namespace {
using name_table::name_of;
using name_table::names_in;
using name_table::parse_name;

// Name and default CFL number: 0.8 x the smallest cfl (of 0.3, 0.4, 0.45, 0.5 ... 1.0) that
// failed on any measured scene, rounded down to 0.05, and no larger than the largest cfl whose
// column load stayed within 1 % of the run at 0.3 (linear: 0.3) (docs/tradeoff.md, "Time step";
// pipelines/tradeoff/cfl-matrix.sh). The failures are a cliff, not a drift: below it the energy
// balance of a run does not depend on the cfl, at it a local burst of kinetic energy in the
// first hundred steps is drained by the transfer and the run stops (the energy-balance check).
// Scenes: paper A's column at cell 0.4 mm (4 cells across); the QUICK T1P20 and T1P40
// lattices (`make lattice-compression QUICK=1`, struts 1.6 cells across), where the old
// defaults 0.5 / 0.6 / 0.7 / 0.9 / 0.5 all stopped within 450 steps (tests/solve/
// thin_lattice_default_cfl.sh); one elastic Ti-6Al-4V T2P30 cell pressed 2.8 mm and released
// (bench/paper_b/lattice_set_study.sh's set-up), where bspline2 at 0.8 and bspline3 at 1.0 rang.
constexpr std::array<std::tuple<ShapeFunctionKind, const char*, double>, 7> shape_names{{
    {ShapeFunctionKind::linear, "linear", 0.3},      // MUSL; at 0.5 the column's load moved 2.9 %, at 0.8 it failed
    {ShapeFunctionKind::ugimp, "ugimp", 0.4},        // thin-strut lattices: 0.5 failed, 0.45 ran
    {ShapeFunctionKind::cpgimp, "cpgimp", 0.4},      // thin-strut lattices: 0.5 failed, 0.45 ran
    {ShapeFunctionKind::bspline2, "bspline2", 0.55}, // thin-strut lattices: 0.7 failed, 0.6 ran
    {ShapeFunctionKind::bspline3, "bspline3", 0.6},  // thin-strut lattices: 0.8 failed, 0.7 ran
    {ShapeFunctionKind::ddmp, "ddmp", 0.4},          // small-mass fraction 0.015: T1P40 0.5 failed, 0.4 ran
                                                     // (0.3 with 0.01 until 2026-11-29: 0.4 failed at step 399)
    {ShapeFunctionKind::cpdi1, "cpdi1", 0.3},        // not measured: the conservative value
}};
constexpr std::array<std::pair<UpdateScheme, const char*>, 3> scheme_names{{
    {UpdateScheme::usl, "usl"}, {UpdateScheme::usf, "usf"}, {UpdateScheme::musl, "musl"}}};
constexpr std::array<std::pair<NullSpaceFilter, const char*>, 3> filter_names{{
    {NullSpaceFilter::none, "none"}, {NullSpaceFilter::deformation, "deformation"},
    {NullSpaceFilter::reference_map, "reference_map"}}};
constexpr std::array<std::pair<MaterialKind, const char*>, 3> material_names{{
    {MaterialKind::linear_elastic, "linear_elastic"}, {MaterialKind::neo_hookean, "neo_hookean"}, {MaterialKind::j2, "j2"}}};
constexpr std::array<std::pair<BodyRole, const char*>, 3> role_names{{
    {BodyRole::deformable, "deformable"}, {BodyRole::fixed, "fixed"}, {BodyRole::driven, "driven"}}};
constexpr std::array<std::pair<RigidShape, const char*>, 2> rigid_shape_names_{{
    {RigidShape::box, "box"}, {RigidShape::half_space, "half_space"}}};
constexpr std::array<std::pair<RigidMotion, const char*>, 4> rigid_motion_names_{{
    {RigidMotion::driven, "driven"}, {RigidMotion::free, "free"}, {RigidMotion::fixed, "fixed"},
    {RigidMotion::scheduled, "scheduled"}}};
constexpr std::array<std::pair<RigidCoupling, const char*>, 2> rigid_coupling_names_{{
    {RigidCoupling::no_slip, "no_slip"}, {RigidCoupling::penalty, "penalty"}}};
constexpr std::array<std::pair<ContactReach, const char*>, 2> contact_reach_names_{{
    {ContactReach::domain, "domain"}, {ContactReach::point, "point"}}};
}  // namespace

std::string to_string(ShapeFunctionKind kind) { return name_of(kind, shape_names); }
ShapeFunctionKind parse_shape_function(const std::string& name, const std::string& where,
                                       const std::string& field) {
  return parse_name(name, shape_names, where, field);
}
std::string to_string(UpdateScheme scheme) { return name_of(scheme, scheme_names); }
UpdateScheme parse_update_scheme(const std::string& name, const std::string& where,
                                 const std::string& field) {
  return parse_name(name, scheme_names, where, field);
}
std::string to_string(NullSpaceFilter filter) { return name_of(filter, filter_names); }
std::vector<std::string> null_space_filter_names() { return names_in(filter_names); }
NullSpaceFilter parse_null_space_filter(const std::string& name, const std::string& where,
                                        const std::string& field) {
  return parse_name(name, filter_names, where, field);
}
std::string to_string(MaterialKind kind) { return name_of(kind, material_names); }
MaterialKind parse_material_kind(const std::string& name, const std::string& where,
                                 const std::string& field) {
  return parse_name(name, material_names, where, field);
}
std::string to_string(BodyRole role) { return name_of(role, role_names); }
std::vector<std::string> shape_function_names() { return names_in(shape_names); }
std::vector<std::string> update_scheme_names() { return names_in(scheme_names); }
std::vector<std::string> material_kind_names() { return names_in(material_names); }
std::vector<std::string> body_role_names() { return names_in(role_names); }
BodyRole parse_body_role(const std::string& name, const std::string& where, const std::string& field) {
  return parse_name(name, role_names, where, field);
}
std::string to_string(RigidShape shape) { return name_of(shape, rigid_shape_names_); }
std::string to_string(RigidMotion motion) { return name_of(motion, rigid_motion_names_); }
std::string to_string(RigidCoupling coupling) { return name_of(coupling, rigid_coupling_names_); }
std::vector<std::string> rigid_shape_names() { return names_in(rigid_shape_names_); }
std::vector<std::string> rigid_motion_names() { return names_in(rigid_motion_names_); }
std::vector<std::string> rigid_coupling_names() { return names_in(rigid_coupling_names_); }
RigidShape parse_rigid_shape(const std::string& name) { return parse_name(name, rigid_shape_names_, "", ""); }
RigidMotion parse_rigid_motion(const std::string& name) { return parse_name(name, rigid_motion_names_, "", ""); }
RigidCoupling parse_rigid_coupling(const std::string& name) { return parse_name(name, rigid_coupling_names_, "", ""); }
std::string to_string(ContactReach reach) { return name_of(reach, contact_reach_names_); }
std::vector<std::string> contact_reach_names() { return names_in(contact_reach_names_); }
ContactReach parse_contact_reach(const std::string& name) { return parse_name(name, contact_reach_names_, "", ""); }

double default_cfl(ShapeFunctionKind shape) {
  for (const auto& [kind, name, cfl] : shape_names)
    if (kind == shape) return cfl;
  return 0.3;
}

UpdateScheme default_scheme(ShapeFunctionKind shape) {
  // Linear shapes keep an O(1/h) gradient at a node that a particle entering an empty cell
  // has just given a tiny mass: USL then inverts that particle (measured: the tiny column at
  // step 1905). MUSL's remapped nodal velocity stays bounded, so it is their default
  // (docs/scene.md). DDMP hands such nodes on to their neighbours and runs USL, as the paper.
  return shape == ShapeFunctionKind::linear ? UpdateScheme::musl : UpdateScheme::usl;
}

}  // namespace latmpm::mpm
