// A simulation scene: what latmpm-solve runs. Read from TOML (docs/scene.md has the full
// key reference); every dimensional value carries its unit in the file and is SI here.
// Reading is separate from building the simulation (pbrt's Create(params) then construct).
// The scene holds the solver's own parameter structs whole (mpm::Settings,
// mpm::MaterialParameters in mpm::BodySettings, mpm::RigidBodySettings),
// each read by one read() in scene/solver_readers.cpp; the choices
// are named by the solver's one table per choice (mpm/names.cpp), and the defaults are the
// structs' own. What is here besides is the scene's: where each value came from (for
// messages), the run's end, outputs, checkpoints and the point files.
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "mpm/body.hpp"
#include "mpm/rigid_body.hpp"
#include "mpm/settings.hpp"

namespace latmpm {

using mpm::BodyRole;

// What a scene can choose (latmpm-solve --list CHOICE), one name a line, from the reader's own
// tables: "shapes" (grid.shape), "schemes" (grid.scheme), "materials" (material.model),
// "boundaries" (the KEY=VALUE choices of fixed, driven and rigid bodies). Empty for another word.
std::vector<std::string> scene_choice_names(const std::string& choice);

// A rigid body given by its geometry ([rigid_bodies.<name>]): no points, no mass on the grid.
// The solver's settings (plane_normal of unit length), and where its table starts.
struct RigidBodySpec : mpm::RigidBodySettings {
  std::string where;
};

// When the run saves RUN_DIR/checkpoint.h5 (latmpm-solve --resume continues from it).
struct CheckpointSpec {
  long every_steps = 0;         // 0: not by steps
  double every_minutes = 10;    // wall-clock minutes; 0: not by time
};

// A body of the point files: the solver's settings (name, role, material, velocity, hold =
// { tag, slip }), and what the scene adds.
struct BodySpec : mpm::BodySettings {
  bool has_material = false;  // deformable bodies always; fixed/driven optionally (mass only)
  std::string hold_where;  // location of the hold.tag key
  // `trim = { point = [...], normal = [...] }`: the body's points beyond this plane,
  // (x − point)·normal > 0, are dropped when the point files are read — e.g. a printed plate
  // kept deformable only in a slice next to the specimen, a rigid half-space on the slice
  // standing for the rest (docs/scene.md). trim_normal zero: no trim.
  Eigen::Vector3d trim_point = Eigen::Vector3d::Zero(), trim_normal = Eigen::Vector3d::Zero();  // m, unit
  std::string trim_where;  // location of the trim.point key
  std::string where;  // "scene.toml:14", for messages about this body
};

struct PointFileSpec {
  std::string path;   // absolute: resolved against the scene file's directory (--set: the current one)
  std::string where;  // location of its 'file' key
};

// How the run ends: at a simulated time or when the driven body has moved a distance.
struct EndCondition {
  enum Kind { time, plate_displacement } kind = time;
  double value = 0;  // s or m
  std::string where;
};

// [solver]: the explicit MPM time stepping (default) or the static equilibrium solve on the
// MPM grid (paper C Sec. 3.3, libs/statics, docs/statics.md), which moves the driven body
// to run.end.plate_displacement in `increments` equilibrium steps.
struct SolverSpec {
  enum Kind { explicit_dynamics, static_equilibrium } kind = explicit_dynamics;
  int increments = 20;                  // static: equilibrium steps to the end travel
  std::string linear_solver = "cholmod";  // static: "cholmod", "ldlt" or "cg"
  double tolerance = 1e-8;              // static: relative residual force of each increment
  bool check_stability = true;          // static: end the path at the first unstable equilibrium
  double stabilisation = 0.1;           // static: β of the affine stabilisation (× shear modulus)
  std::string where;
};

struct Scene {
  std::string source;  // the scene file as named by the user
  EndCondition end;
  long max_steps = 0;  // 0: no limit

  // [grid], [time], [gravity] and output.record_tag: the solver's settings as the scene gives
  // them (threads are the command line's). cfl's default is mpm::default_cfl(shape), the
  // scheme's mpm::default_scheme(shape).
  mpm::Settings settings;
  // [time] quasi_static = { load_error = 0.03 }: mass_scaling picked by the quasi-static mode
  // (quasi_static_mode.hpp) for this bound on the load error (fraction of the peak); 0: off.
  double quasi_static_load_error = 0;
  std::string quasi_static_note;  // the mode's pick and why, for the log

  std::vector<PointFileSpec> point_files;
  std::vector<BodySpec> bodies;  // in document order
  // Bodies of the point files that the scene leaves out (role = "omitted"): their points are
  // dropped when the files are read, e.g. printed plates that [rigid_bodies] model as
  // geometry instead (docs/scene.md). Name order; `where` names their role key.
  std::vector<BodySpec> omitted_bodies;
  std::vector<RigidBodySpec> rigid_bodies;  // in document order
  CheckpointSpec checkpoint;

  long series_every = 100;    // steps between series rows
  long snapshot_every = 0;    // steps between particle snapshots, 0 = first and last only
  SolverSpec solver;
  std::string record_where;  // location of output.record_tag when the scene sets it, else empty

  // The scene as run: the document after --set overrides, with every default filled in
  // and point-file paths made absolute. Written to RUN_DIR/scene.toml.
  std::string resolved_toml;

  const BodySpec* body(const std::string& name) const;
  std::string where;  // "scene.toml", for messages about the scene as a whole
};

// Reads a scene file and applies "key.path=value" overrides (latmpm-solve --set).
// Throws InputError "FILE:LINE: key.path: problem" (or "--set key=value: ...") for syntax
// errors, unknown keys, missing keys, wrong types, values without or with the wrong unit.
Scene read_scene(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from text (tests); `name` stands for the file in messages, `directory` resolves
// relative point-file paths.
Scene parse_scene(const std::string& text, const std::string& name, const std::string& directory,
                  const std::vector<std::string>& overrides = {});

}  // namespace latmpm
