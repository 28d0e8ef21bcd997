// Run directories written by hand, as latmpm-solve would leave them (docs/scene.md): a
// series.csv, a scene.toml naming a point file, a log.txt ending in a status line. Lets the
// post-processing tests know every number in advance.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace latmpm::test {

struct SyntheticRun {
  std::string status = "finished";  // "finished", "failed", "max_steps", "" (no status line)
  std::string cell = "tetrahedral"; // /points/parameters/cell ("column" makes a column run)
  double strut_diameter = 1.6e-3, strut_length = 16e-3;  // m
  double lattice_zmin = 3e-3, lattice_zmax = 43e-3;      // m: gauge length 40 mm
  double footprint_area = 0;                             // m²; 0: not recorded
  double youngs_modulus = 10e6, density = 1050;          // Pa, kg/m³
  int deformable_points = 10;
  double point_volume = 1e-9;                            // m³
  bool write_points = true;                              // false: the scene names a missing file
};

// Writes `dir` (created) with series.csv from the rows of f(t) at times t0..tn:
// columns step,time,dt,displacement,load_driven,load_fixed,load_record,... plus `extra` ones.
struct SeriesSpec {
  std::vector<double> time, displacement, load;
  std::vector<std::pair<std::string, std::vector<double>>> extra;  // name[unit] -> values
};
void write_synthetic_run(const std::string& dir, const SyntheticRun& run, const SeriesSpec& series);

// The same series as text (header and rows), for tests that cut it.
std::string series_csv_text(const SeriesSpec& series);

}  // namespace latmpm::test
