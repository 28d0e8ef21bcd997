#include "scene/solver_readers.hpp"

#include <limits>
#include <string>

namespace latmpm::scene_toml {

void read(TableReader& grid, TableReader& time, TableReader& gravity, TableReader& output,
          mpm::Settings& s) {
  s.cell_size = grid.quantity("cell", dimension::length);
  if (!(s.cell_size > 0)) grid.fail("cell", "must be positive");
  s.shape_function = mpm::parse_shape_function(
      grid.choice("shape", mpm::shape_function_names(), mpm::to_string(s.shape_function)));
  s.scheme = mpm::parse_update_scheme(
      grid.choice("scheme", mpm::update_scheme_names(), mpm::to_string(mpm::default_scheme(s.shape_function))));
  s.flip_blend = grid.number("flip", s.flip_blend);
  if (s.flip_blend < 0 || s.flip_blend > 1) grid.fail("flip", "must lie in [0, 1] (1 = FLIP, 0 = PIC)");
  s.null_space_filter = mpm::parse_null_space_filter(
      grid.choice("null_space_filter", mpm::null_space_filter_names(), mpm::to_string(s.null_space_filter)));
  const long every = grid.integer("null_space_filter_every", s.null_space_filter_every);
  if (every < 1 || every > std::numeric_limits<int>::max()) grid.fail("null_space_filter_every", "must be at least 1 (steps)");
  s.null_space_filter_every = int(every);
  s.ddmp_alpha_peak = grid.number("ddmp_alpha_peak", s.ddmp_alpha_peak);
  if (!(s.ddmp_alpha_peak > 0 && s.ddmp_alpha_peak <= 1)) grid.fail("ddmp_alpha_peak", "must lie in (0, 1]");
  s.ddmp_alpha_exponent = grid.number("ddmp_alpha_exponent", s.ddmp_alpha_exponent);
  if (!(s.ddmp_alpha_exponent > 0)) grid.fail("ddmp_alpha_exponent", "must be positive");
  s.ddmp_on_grid = grid.boolean("ddmp_on_grid", s.ddmp_on_grid);
  s.ddmp_subpoints = grid.boolean("ddmp_subpoints", s.ddmp_subpoints);
  if (s.ddmp_subpoints && !(s.shape_function == mpm::ShapeFunctionKind::ddmp && s.ddmp_on_grid))
    grid.fail("ddmp_subpoints", "needs shape = \"ddmp\" with ddmp_on_grid = true");
  s.ddmp_small_mass_fraction = grid.number("ddmp_small_mass_fraction", s.ddmp_small_mass_fraction);
  if (!(s.ddmp_small_mass_fraction >= 0 && s.ddmp_small_mass_fraction < 1))
    grid.fail("ddmp_small_mass_fraction", "must lie in [0, 1)");
  // The stabilization belongs to DDMP on the grid without sub-points; the per-particle
  // reference form and the sub-points study run Paper A's DDMP unless the key asks otherwise.
  const bool stabilizable = s.ddmp_on_grid && !s.ddmp_subpoints;
  s.ddmp_stabilization = grid.number("ddmp_stabilization", stabilizable ? s.ddmp_stabilization : 0);
  if (!(s.ddmp_stabilization >= 0 && s.ddmp_stabilization <= 1))
    grid.fail("ddmp_stabilization", "must lie in [0, 1] (a fraction of the body's elastic moduli)");
  if (s.ddmp_stabilization > 0 && !stabilizable)
    grid.fail("ddmp_stabilization", "needs ddmp_on_grid = true without ddmp_subpoints (or 0)");

  if (time.has("dt") && time.has("cfl"))
    time.fail("dt", "give either dt (a fixed step) or cfl (a step from the wave speed), not both");
  if (time.has("dt")) {
    s.fixed_time_step = time.quantity("dt", dimension::time);
    if (!(s.fixed_time_step > 0)) time.fail("dt", "must be positive");
  } else {
    s.cfl = time.number("cfl", mpm::default_cfl(s.shape_function));
    if (!(s.cfl > 0) || s.cfl > 1) time.fail("cfl", "must lie in (0, 1]");
  }
  if (!time.has("quasi_static")) {  // else the quasi-static mode picks it (Scene)
    s.mass_scaling = time.number("mass_scaling", s.mass_scaling);
    if (!(s.mass_scaling > 0)) time.fail("mass_scaling", "must be positive");
  }

  s.gravity = gravity.vector("g", dimension::acceleration, "0m/s^2");
  s.record_tag = output.text("record_tag", s.record_tag);
}

void read(TableReader& m, mpm::MaterialParameters& p) {
  p.kind = mpm::parse_material_kind(m.choice("model", mpm::material_kind_names(), mpm::to_string(p.kind)));
  p.young_modulus = m.quantity("E", dimension::pressure);
  if (!(p.young_modulus > 0)) m.fail("E", "must be positive");
  p.poisson_ratio = m.number("nu");
  if (!(p.poisson_ratio > -1 && p.poisson_ratio < 0.5)) m.fail("nu", "must lie in (-1, 0.5)");
  p.density = m.quantity("density", dimension::density);
  if (!(p.density > 0)) m.fail("density", "must be positive");
  if (p.kind == mpm::MaterialKind::j2) {  // paper B Eq. 10; the other models refuse these keys
    p.initial_yield = m.quantity("y0", dimension::pressure);
    if (!(p.initial_yield > 0)) m.fail("y0", "must be positive");
    p.saturation_yield = m.has("y_inf") ? m.quantity("y_inf", dimension::pressure) : p.initial_yield;
    if (!(p.saturation_yield > 0)) m.fail("y_inf", "must be positive");
    p.saturation_rate = m.number("eta", p.saturation_rate);
    if (!(p.saturation_rate >= 0)) m.fail("eta", "must be zero or positive");
    p.linear_hardening = m.quantity("h", dimension::pressure, "0Pa");
    if (!(p.linear_hardening >= 0)) m.fail("h", "must be zero or positive");
  }
}

namespace {
// contact = { model, friction, stiffness, reach }: how a rigid body acts on the material.
void read_contact(TableReader& b, mpm::RigidBodySettings& body) {
  auto contact = b.optional_table("contact");
  if (!contact) return;
  body.coupling = mpm::parse_rigid_coupling(
      contact->choice("model", mpm::rigid_coupling_names(), mpm::to_string(mpm::RigidCoupling::no_slip)));
  if (body.coupling == mpm::RigidCoupling::no_slip) {
    for (const char* key : {"friction", "stiffness", "reach"})
      if (contact->has(key)) contact->fail(key, "only penalty contact (model = \"penalty\") takes it");
  } else {
    // μ: a number ≥ 0 (0 slides freely) or "stick" (never slides).
    if (contact->has_text("friction")) {
      if (contact->text("friction") != "stick")
        contact->fail("friction", "expected a number >= 0 or \"stick\"");
      body.friction = std::numeric_limits<double>::infinity();
    } else {
      body.friction = contact->number("friction");
      if (!(body.friction >= 0)) contact->fail("friction", "must be 0 (frictionless) or positive");
    }
    if (contact->has("stiffness")) {
      body.contact_stiffness = contact->quantity("stiffness", dimension::stiffness);
      if (!(body.contact_stiffness > 0)) contact->fail("stiffness", "must be positive (leave it out for the default)");
    }
    body.contact_reach = mpm::parse_contact_reach(
        contact->choice("reach", mpm::contact_reach_names(), mpm::to_string(mpm::ContactReach::domain)));
  }
  contact->finish();
}

// schedule = [{ time = "0s", velocity = [...] }, ...]: a scheduled body's velocity against time,
// linear between knots (motion_schedule.hpp); its `velocity` is the schedule's.
void read_schedule(TableReader& b, mpm::RigidBodySettings& body) {
  if (b.has("velocity")) b.fail("velocity", "a scheduled body takes its velocity from its schedule: leave it out");
  for (TableReader& knot : b.tables("schedule")) {
    mpm::VelocityKnot k;
    k.time = knot.quantity("time", dimension::time);
    k.velocity = knot.vector("velocity", dimension::velocity);
    knot.finish();
    const size_t i = body.schedule.knots.size();
    if (i == 0 && k.time != 0) knot.fail("time", "the first knot must be at time 0 (where the run starts)");
    if (i > 0 && !(k.time > body.schedule.knots.back().time))
      knot.fail("time", "must be later than the knot before it (times increase strictly)");
    body.schedule.knots.push_back(k);
  }
  body.velocity = body.schedule.velocity(0);
}
}  // namespace

void read(TableReader& b, mpm::RigidBodySettings& body) {
  body.motion = mpm::parse_rigid_motion(b.choice("motion", mpm::rigid_motion_names(), ""));
  body.shape = mpm::parse_rigid_shape(b.choice("shape", mpm::rigid_shape_names(), mpm::to_string(body.shape)));
  if (body.shape == mpm::RigidShape::box) {
    body.box_min = b.vector("min", dimension::length);
    body.box_max = b.vector("max", dimension::length);
    for (int a = 0; a < 3; ++a)
      if (!(body.box_max[a] > body.box_min[a])) b.fail("max", "must exceed min along every axis (an empty box)");
  } else {
    body.plane_point = b.vector("point", dimension::length);
    body.plane_normal = b.vector("normal", dimension::none);
    if (!(body.plane_normal.norm() > 0)) b.fail("normal", "must be a non-zero direction (out of the body)");
    body.plane_normal = body.plane_normal.normalized();
  }
  const std::string motion = mpm::to_string(body.motion);
  if (body.motion == mpm::RigidMotion::driven) {
    body.velocity = b.vector("velocity", dimension::velocity);
    if (body.velocity.norm() == 0) b.fail("velocity", "a driven body needs a non-zero velocity");
  } else if (body.motion == mpm::RigidMotion::free) {
    body.velocity = b.vector("velocity", dimension::velocity, "0m/s");
    body.mass = b.quantity("mass", dimension::mass);
    if (!(body.mass > 0)) b.fail("mass", "must be positive");
    body.gravity = b.boolean("gravity", body.gravity);
  } else if (body.motion == mpm::RigidMotion::scheduled) {
    read_schedule(b, body);
  } else if (b.has("velocity")) {
    b.fail("velocity", "a fixed rigid body stays at rest: it takes no velocity");
  }
  if (body.motion != mpm::RigidMotion::scheduled && b.has("schedule"))
    b.fail("schedule", "only a scheduled body (motion = \"scheduled\") takes a schedule (this one is " + motion + ")");
  if (body.motion != mpm::RigidMotion::free) {
    if (b.has("mass")) b.fail("mass", "only free rigid bodies take a mass (this one is " + motion + ")");
    if (b.has("gravity")) b.fail("gravity", "only free rigid bodies take gravity (this one is " + motion + ")");
  }
  read_contact(b, body);
}

void read(TableReader& solver, statics::StaticSettings& s) {
  s.increments = int(solver.integer("increments", s.increments));
  if (s.increments < 1) solver.fail("increments", "must be at least 1");
  s.linear_solver = statics::parse_linear_solver(
      solver.choice("linear_solver", statics::linear_solver_names(), statics::to_string(s.linear_solver)));
  s.tolerance = solver.number("tolerance", s.tolerance);
  if (!(s.tolerance > 0 && s.tolerance < 1)) solver.fail("tolerance", "must lie in (0, 1)");
  s.check_stability = solver.boolean("check_stability", s.check_stability);
  s.predictor = solver.boolean("predictor", s.predictor);
  s.max_increment_growth = solver.number("max_increment_growth", s.max_increment_growth);
  if (!(s.max_increment_growth >= 1)) solver.fail("max_increment_growth", "must be at least 1 (1: fixed increments)");
  const long krylov_iterations = solver.integer("krylov_iterations", s.krylov_iterations);
  if (krylov_iterations < 0 || krylov_iterations > 100000)
    solver.fail("krylov_iterations", "must lie in [0, 100000] (0: every Newton step factorises)");
  s.krylov_iterations = int(krylov_iterations);
  const long newton_iterations = solver.integer("newton_iterations", s.newton_iterations);
  if (newton_iterations < 1 || newton_iterations > 10000)
    solver.fail("newton_iterations", "must lie in [1, 10000] (Newton steps of an increment)");
  s.newton_iterations = int(newton_iterations);
  const long bisections = solver.integer("bisections", s.bisections);
  if (bisections < 0 || bisections > 60) solver.fail("bisections", "must lie in [0, 60] (halvings of the step after a Newton failure)");
  s.bisections = int(bisections);
  const long stall_window = solver.integer("stall_window", s.stall_window);
  if (stall_window < 0 || stall_window > 10000)
    solver.fail("stall_window", "must lie in [0, 10000] (projected Newton steps of steady linear convergence; 0: off)");
  s.stall_window = int(stall_window);
  s.stabilisation = solver.number("stabilisation", s.stabilisation);
  if (!(s.stabilisation >= 0 && s.stabilisation < 1)) solver.fail("stabilisation", "must lie in [0, 1)");
}

namespace {
// A comma-separated list of names (spaces around each trimmed); an empty entry fails.
std::vector<std::string> name_list(TableReader& table, const std::string& key, const std::string& what) {
  const std::string list = table.text(key, "");
  std::vector<std::string> names;
  for (size_t start = 0; start <= list.size();) {
    size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    std::string name = list.substr(start, end - start);
    name.erase(0, name.find_first_not_of(' '));
    name.erase(name.find_last_not_of(' ') + 1);
    if (!name.empty()) names.push_back(name);
    else if (end < list.size()) table.fail(key, "has an empty " + what + " name ('" + list + "')");
    start = end + 1;
  }
  return names;
}
}  // namespace

void read(TableReader& contact, mpm::FieldContactSettings& s) {
  s.enabled = true;
  s.friction = contact.number("friction", s.friction);
  if (!(s.friction >= 0)) contact.fail("friction", "must be zero or positive (a Coulomb coefficient)");
  s.fill = contact.number("fill", s.fill);
  if (!(s.fill >= 0 && s.fill <= 1)) contact.fail("fill", "must lie in [0, 1] (a fraction of the node's volume h^3)");
  // Point tags (a trailing * matches every tag it starts): each tagged part of a body is a field of its own.
  s.groups = name_list(contact, "groups", "tag");
  // Bodies glued where they meet (a lattice and its printed plate).
  s.bonded_bodies = name_list(contact, "bond", "body");
}

}  // namespace latmpm::scene_toml
