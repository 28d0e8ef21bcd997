// A simulation scene: what latmpm-solve runs. Read from TOML (docs/scene.md has the full
// key reference); every dimensional value carries its unit in the file and is SI here.
// Reading is separate from building the simulation (pbrt's Create(params) then construct).
// The choices (shape function, update scheme, material model) are the solver's own
// enumerations, named by the solver's one table per choice (mpm/names.cpp), and the
// defaults the scene shares with the solver come from mpm::Settings.
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "mpm/material.hpp"
#include "mpm/settings.hpp"
#include "mpm/shape_function_kind.hpp"

namespace latmpm {

enum class BodyRole { deformable, fixed, driven };

const char* to_string(BodyRole role);

// What a scene can choose (latmpm-solve --list CHOICE), one name a line, from the reader's own
// tables: "shapes" (grid.shape), "schemes" (grid.scheme), "materials" (material.model),
// "boundaries" (the KEY=VALUE choices of fixed, driven and rigid bodies). Empty for another word.
std::vector<std::string> scene_choice_names(const std::string& choice);

// A rigid body given by its geometry ([rigid_bodies.<name>]): no points, no mass on the grid.
struct RigidBodySpec {
  enum Shape { box, half_space } shape = box;
  enum Motion { driven, free, fixed } motion = driven;
  Eigen::Vector3d min = Eigen::Vector3d::Zero(), max = Eigen::Vector3d::Zero();  // m (box)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();                                // m (half_space)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // out of the body, toward the specimen
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s: prescribed (driven), initial (free), 0 (fixed)
  double mass = 0;       // kg (free)
  bool gravity = true;   // free: gravity acts on it
  // contact = { model = "penalty", friction = 0.1, stiffness = "2e4N/m" }: penalty contact of
  // the points against its surface with Coulomb friction instead of no-slip grid coupling.
  enum Contact { no_slip, penalty } contact = no_slip;
  double friction = 0;           // μ ≥ 0; infinity for "stick"
  double contact_stiffness = 0;  // N/m per point; 0: the solver's default from the material
  std::string name;
  std::string where;
};

// When the run saves RUN_DIR/checkpoint.h5 (latmpm-solve --resume continues from it).
struct CheckpointSpec {
  long every_steps = 0;         // 0: not by steps
  double every_minutes = 10;    // wall-clock minutes; 0: not by time
};

struct MaterialSpec {
  mpm::MaterialKind model = mpm::MaterialKind::linear_elastic;
  double youngs_modulus = 0;  // Pa
  double poisson_ratio = 0;
  double density = 0;  // kg/m³ as given; mass scaling is applied by the solver set-up
  // model = "j2" (paper B Eq. 10): y0, y_inf (default y0), eta (default 0), h (default 0).
  double initial_yield = 0;     // Pa
  double saturation_yield = 0;  // Pa
  double saturation_rate = 0;   // dimensionless
  double linear_hardening = 0;  // Pa
};

struct BodySpec {
  std::string name;
  BodyRole role = BodyRole::deformable;
  bool has_material = false;  // deformable bodies always; fixed/driven optionally (mass only)
  MaterialSpec material;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // m/s, driven bodies
  // Deformable bodies: `hold = { tag = "record" }` holds the body's points with this point
  // tag at rest (zero velocity on the grid nodes they reach). Empty: none held.
  std::string hold_tag;
  bool hold_slip = false;  // hold.slip: only the velocity normal to the held face is zero
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
  std::string linear_solver = "auto";  // static: "auto", "cholmod", "amg", "ldlt" or "cg"
  double tolerance = 1e-8;              // static: relative residual force of each increment
  bool check_stability = true;          // static: end the path at the first unstable equilibrium
  double stabilisation = 0.1;           // static: β of the affine stabilisation (× shear modulus)
  std::string where;
};

struct Scene {
  std::string source;  // the scene file as named by the user
  EndCondition end;
  long max_steps = 0;  // 0: no limit

  double cell_size = 0;  // m; 0 = take the point files' cell size
  mpm::ShapeFunctionKind shape = mpm::ShapeFunctionKind::ugimp;
  mpm::UpdateScheme scheme = mpm::UpdateScheme::usl;
  double flip = mpm::Settings{}.flip_blend;  // FLIP fraction of the velocity update (1 = pure FLIP, 0 = PIC)
  // DDMP partition function α: value at the cell centre and per-axis exponent
  // (mpm::Settings); the defaults are paper A's Eq. 5 in 3D.
  double ddmp_alpha_peak = mpm::Settings{}.ddmp_alpha_peak;
  double ddmp_alpha_exponent = mpm::Settings{}.ddmp_alpha_exponent;
  bool ddmp_on_grid = mpm::Settings{}.ddmp_on_grid;  // DDMP's smoothed gradient on the grid

  // Used when dt == 0; read: mpm::default_cfl(shape), the shape function's measured limit.
  double cfl = 0.3;
  double dt = 0;         // s, fixed step when > 0
  double mass_scaling = 1;  // multiplies every deformable body's density (paper A Sec. 4: 6)
  // [time] quasi_static = { load_error = 0.03 }: mass_scaling picked by the quasi-static mode
  // (quasi_static_mode.hpp) for this bound on the load error (fraction of the peak); 0: off.
  double quasi_static_load_error = 0;
  std::string quasi_static_note;  // the mode's pick and why, for the log

  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // m/s²

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
  std::string record_tag = "record";  // point tag of the record layer (paper A Sec. 5.1)
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
