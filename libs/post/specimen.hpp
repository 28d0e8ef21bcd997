// What the metrics need to know about the specimen of a run, found from the run's resolved
// scene (RUN_DIR/scene.toml) and the point files it names: the deformable material (E,
// density), the specimen mass, and the geometry parameters the lattice/column tools recorded
// (docs/formats.md, /points/parameters). Read leniently: a fact that cannot be found stays NaN
// (or empty) and `notes` says why, so one missing point file costs the metrics that need it,
// not the whole run.
#pragma once
#include <limits>
#include <string>
#include <vector>

namespace latmpm::post {

struct SpecimenFacts {
  static constexpr double unknown = std::numeric_limits<double>::quiet_NaN();

  std::vector<std::string> deformable_bodies;  // scene order
  double youngs_modulus = unknown;  // Pa, of the first deformable body
  double density = unknown;         // kg/m³ as given in the scene (before mass scaling)
  double mass_scaling = 1;          // [time] mass_scaling
  // kg: Σ volume × density over the deformable bodies' points, with the density as given
  // (the real material, not mass-scaled: SEA is a property of the printed part).
  double mass = unknown;
  // From the point files' /points/parameters.
  std::string cell;                   // "column", "tetrahedral", ...
  double strut_diameter = unknown;    // m (t)
  double strut_length = unknown;      // m (L)
  double gauge_length = unknown;      // m, lattice_zmax − lattice_zmin: the height strain refers to
  double footprint_area = unknown;    // m², the struts' x–y bounding box (latmpm-lattice)
  std::vector<std::string> point_files;
  std::vector<std::string> notes;     // facts that could not be found, and why
};

// Reads scene.toml (as written by latmpm-solve) and the point files it names.
// Throws InputError(scene_path, key, problem) only when the file is not a TOML scene at all.
SpecimenFacts read_specimen_facts(const std::string& scene_path);

}  // namespace latmpm::post
