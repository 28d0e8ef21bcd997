// The scene schema: which keys each table holds, their units, defaults and ranges.
// docs/scene.md is the reference for users; keep the two in step.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "scene/scene.hpp"
#include "scene/quasi_static_mode.hpp"
#include "scene/solver_readers.hpp"
#include "scene/toml_table_reader.hpp"

namespace latmpm {
namespace {

using scene_toml::Origins;
using scene_toml::TableReader;
namespace fs = std::filesystem;

// A body of the point files that the scene leaves out (Scene::omitted_bodies).
const std::string omitted_role = "omitted";

void read_run(TableReader run, Scene& s) {
  TableReader end = run.table("end");
  const bool by_time = end.has("time"), by_displacement = end.has("plate_displacement");
  if (by_time == by_displacement)
    run.fail("end", "give exactly one of { time = \"...\" } or { plate_displacement = \"...\" }");
  s.end.kind = by_time ? EndCondition::time : EndCondition::plate_displacement;
  s.end.value = by_time ? end.quantity("time", dimension::time)
                        : end.quantity("plate_displacement", dimension::length);
  s.end.where = end.where(by_time ? "time" : "plate_displacement");
  if (!(s.end.value > 0)) end.fail(by_time ? "time" : "plate_displacement", "must be positive");
  end.finish();
  s.max_steps = run.integer("max_steps", 0);
  if (s.max_steps < 0) run.fail("max_steps", "must be 0 (no limit) or positive");
  run.finish();
}

// [grid], [time], [gravity] and [output]: the solver's settings (solver_readers.hpp), and
// the scene's own keys of those tables.
void read_settings_and_output(TableReader& root, Scene& s) {
  TableReader grid = root.table("grid"), time = root.table_or_empty("time"),
              gravity = root.table_or_empty("gravity"), out = root.table_or_empty("output");
  // Before read(): it inserts record_tag's default, after which the key is always there. The
  // default tag is no request either when written out: the resolved scene (RUN_DIR/scene.toml,
  // which --resume reads) names it, and a run without record points must resume.
  if (out.has("record_tag") && out.text("record_tag", "") != mpm::Settings{}.record_tag)
    s.record_where = out.where("record_tag");
  read(grid, time, gravity, out, s.settings);
  grid.finish();
  if (auto qs = time.optional_table("quasi_static")) {
    if (time.has("mass_scaling"))
      qs->fail("load_error", "the quasi-static mode picks the mass scaling: give either it or mass_scaling");
    s.quasi_static_load_error = qs->number("load_error");
    if (!(s.quasi_static_load_error > 0 && s.quasi_static_load_error < 1))
      qs->fail("load_error", "must lie in (0, 1) (a fraction of the peak load)");
    qs->finish();
  }
  time.finish();
  gravity.finish();
  s.series_every = out.integer("series_every", 100);
  if (s.series_every < 1) out.fail("series_every", "must be at least 1 (steps between rows)");
  s.snapshot_every = out.integer("snapshot_every", 0);
  if (s.snapshot_every < 0) out.fail("snapshot_every", "must be 0 (first and last only) or positive");
  out.finish();
}

void read_points(std::vector<TableReader> files, const std::string& directory, Scene& s) {
  for (TableReader& f : files) {
    std::string file = f.text("file");
    fs::path p(file);
    // Relative to the scene file's directory; a path given with --set is relative to the
    // current directory, like any other path typed on the command line.
    if (p.is_relative() && !f.overridden("file")) p = fs::path(directory) / p;
    p = fs::absolute(p).lexically_normal();
    if (!fs::is_regular_file(p)) f.fail("file", "cannot find point file '" + p.string() + "'");
    s.point_files.push_back({p.string(), f.where("file")});
    f.replace_text("file", p.string());  // after where(): the new value has no source line
    f.finish();
  }
  if (s.point_files.empty()) throw InputError(s.where, "points", "the scene names no point file ([[points]] file = \"...\")");
}

void read_bodies(TableReader bodies, Scene& s) {
  for (const std::string& name : bodies.keys()) {
    TableReader b = bodies.table(name);
    BodySpec body;
    body.name = name;
    body.where = b.where("role");
    std::vector<std::string> roles = mpm::body_role_names();
    roles.push_back(omitted_role);
    const std::string role = b.choice("role", roles, "");
    if (role == omitted_role) {  // no other key: nothing of it is simulated
      b.finish();
      s.omitted_bodies.push_back(body);
      continue;
    }
    body.role = mpm::parse_body_role(role);
    if (body.role == BodyRole::deformable || b.has("material")) {
      TableReader material = b.table("material");
      read(material, body.material);
      material.finish();
      body.has_material = true;
    }
    if (body.role == BodyRole::driven) {
      body.velocity = b.vector("velocity", dimension::velocity);
      if (body.velocity.norm() == 0) b.fail("velocity", "a driven body needs a non-zero velocity");
    } else if (b.has("velocity")) {
      b.fail("velocity", std::string("only driven bodies take a velocity (this one is ") +
                             to_string(body.role) + ")");
    }
    if (auto hold = b.optional_table("hold")) {
      body.hold_where = hold->where("tag");
      body.hold_tag = hold->text("tag");
      if (body.role != BodyRole::deformable)
        hold->fail("tag", std::string("only deformable bodies hold tagged points (this one is ") +
                              to_string(body.role) + ", constrained as a whole)");
      if (body.hold_tag.empty()) hold->fail("tag", "must name a point tag");
      body.hold_slip = hold->boolean("slip", false);
      hold->finish();
    }
    if (auto trim = b.optional_table("trim")) {
      body.trim_where = trim->where("point");
      body.trim_point = trim->vector("point", dimension::length);
      body.trim_normal = trim->vector("normal", dimension::none);
      if (!(body.trim_normal.norm() > 0)) trim->fail("normal", "must be a non-zero direction (toward the points to drop)");
      body.trim_normal.normalize();
      trim->finish();
    }
    b.finish();
    s.bodies.push_back(body);
  }
  bodies.finish();
  // Bodies in name order, not document order: the resolved scene (RUN_DIR/scene.toml) lists
  // tables alphabetically, and a resumed run must number the bodies as the first run did.
  std::stable_sort(s.bodies.begin(), s.bodies.end(), [](const BodySpec& a, const BodySpec& b) { return a.name < b.name; });
}

void read_rigid_bodies(TableReader rigid, Scene& s) {
  for (const std::string& name : rigid.keys()) {
    TableReader b = rigid.table(name);
    RigidBodySpec body;
    body.name = name;
    body.where = b.where("motion");
    read(b, body);
    b.finish();
    if (s.body(name)) b.fail("motion", "a point body of the same name exists; give the rigid body another name");
    s.rigid_bodies.push_back(body);
  }
  rigid.finish();
  std::stable_sort(s.rigid_bodies.begin(), s.rigid_bodies.end(),
                   [](const RigidBodySpec& a, const RigidBodySpec& b) { return a.name < b.name; });
}

void read_checkpoint(TableReader checkpoint, Scene& s) {
  s.checkpoint.every_steps = checkpoint.integer("every_steps", 0);
  if (s.checkpoint.every_steps < 0) checkpoint.fail("every_steps", "must be 0 (off) or positive");
  s.checkpoint.every_minutes = checkpoint.number("every_minutes", 10.0);
  if (!(s.checkpoint.every_minutes >= 0)) checkpoint.fail("every_minutes", "must be 0 (off) or positive");
  checkpoint.finish();
}

void read_solver(TableReader solver, Scene& s) {
  SolverSpec& spec = s.solver;
  spec.where = solver.where("kind");
  spec.kind = solver.choice("kind", {"explicit", "static"}, "explicit") == "static" ? SolverSpec::static_equilibrium
                                                                                   : SolverSpec::explicit_dynamics;
  if (spec.kind == SolverSpec::static_equilibrium) {
    read(solver, spec.statics);
    if (s.end.kind != EndCondition::plate_displacement)
      solver.fail("kind", "a static solve needs run.end = { plate_displacement = \"...\" }");
  }
  solver.finish();
}

// Cross-section checks: what one table alone cannot know.
void check_consistency(const Scene& s) {
  int driven = 0;
  for (const auto& b : s.bodies) driven += b.role == BodyRole::driven;
  for (const auto& b : s.rigid_bodies) driven += b.motion == mpm::RigidMotion::driven;
  if (s.end.kind == EndCondition::plate_displacement && driven != 1)
    throw InputError(s.end.where, "run.end.plate_displacement",
                     "needs exactly one driven body, the scene has " + std::to_string(driven));
}

}  // namespace

std::vector<std::string> scene_choice_names(const std::string& choice) {
  if (choice == "shapes") return mpm::shape_function_names();
  if (choice == "schemes") return mpm::update_scheme_names();
  if (choice == "materials") return mpm::material_kind_names();
  if (choice != "boundaries") return {};
  std::vector<std::string> names;
  for (const auto& role : mpm::body_role_names())
    if (role != mpm::to_string(BodyRole::deformable)) names.push_back("bodies.role=" + role);
  for (const auto& m : mpm::rigid_motion_names()) names.push_back("rigid_bodies.motion=" + m);
  for (const auto& m : mpm::rigid_shape_names()) names.push_back("rigid_bodies.shape=" + m);
  for (const auto& m : mpm::rigid_coupling_names()) names.push_back("rigid_bodies.contact.model=" + m);
  return names;
}

const BodySpec* Scene::body(const std::string& name) const {
  for (const auto& b : bodies)
    if (b.name == name) return &b;
  return nullptr;
}

Scene parse_scene(const std::string& text, const std::string& name, const std::string& directory,
                  const std::vector<std::string>& overrides) {
  toml::table document;
  try {
    document = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    throw InputError(name + ":" + std::to_string(e.source().begin.line), "",
                     "not valid TOML: " + std::string(e.description()));
  }
  Origins origins(name);
  for (const auto& o : overrides) scene_toml::apply_override(document, o, origins);

  Scene s;
  s.source = s.where = name;
  TableReader root(document, "", origins);
  read_run(root.table("run"), s);
  read_settings_and_output(root, s);
  read_points(root.tables("points"), directory, s);
  read_bodies(root.table("bodies"), s);
  if (s.bodies.empty()) root.fail("bodies", "the scene describes no body ([bodies.<name>] tables)");
  if (root.has("rigid_bodies")) read_rigid_bodies(root.table("rigid_bodies"), s);
  read_checkpoint(root.table_or_empty("checkpoint"), s);
  read_solver(root.table_or_empty("solver"), s);
  if (auto contact = root.optional_table("contact")) {
    scene_toml::read(*contact, s.settings.field_contact);
    contact->finish();
  }
  root.finish();
  check_consistency(s);
  if (s.quasi_static_load_error > 0) {
    const QuasiStaticChoice pick = choose_quasi_static(s, s.quasi_static_load_error);
    s.settings.mass_scaling = pick.mass_scaling;
    s.quasi_static_note = pick.reason;
  }

  std::ostringstream os;
  // Shortest round-trip floats: "nu = 0.4", not 0.40000000000000002.
  os << toml::toml_formatter(document, toml::toml_formatter::default_flags |
                                           toml::format_flags::relaxed_float_precision)
     << "\n";
  s.resolved_toml = os.str();
  return s;
}

Scene read_scene(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot read the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  fs::path dir = fs::path(path).parent_path();
  return parse_scene(text.str(), path, dir.empty() ? "." : dir.string(), overrides);
}

}  // namespace latmpm
