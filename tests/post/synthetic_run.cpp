#include "synthetic_run.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"
#include "points/point_set.hpp"

namespace latmpm::test {

namespace fs = std::filesystem;

std::string series_csv_text(const SeriesSpec& s) {
  std::string text = "step[1],time[s],dt[s],displacement[m],load_driven[N],load_fixed[N],load_record[N]";
  for (const auto& [name, values] : s.extra) text += "," + name;
  text += "\n";
  char cell[64];
  for (size_t i = 0; i < s.time.size(); ++i) {
    std::snprintf(cell, sizeof cell, "%zu", i);
    text += cell;
    for (double v : {s.time[i], 1e-6, s.displacement[i], s.load[i], 0.98 * s.load[i], 0.0}) {
      std::snprintf(cell, sizeof cell, ",%.17g", v);
      text += cell;
    }
    for (const auto& [name, values] : s.extra) {
      std::snprintf(cell, sizeof cell, ",%.17g", values[i]);
      text += cell;
    }
    text += "\n";
  }
  return text;
}

void write_synthetic_run(const std::string& dir, const SyntheticRun& r, const SeriesSpec& series) {
  fs::create_directories(dir);
  const std::string points_file = (fs::absolute(dir) / "points.h5").string();
  if (r.write_points) {
    PointSet p;
    p.body_names = {"lattice", "bottom_plate", "top_plate"};
    p.cell_size = 1e-3;
    p.ppc = 1;
    for (int i = 0; i < r.deformable_points + 6; ++i) {
      p.position.emplace_back(0, 0, 1e-3 * i);
      p.volume.push_back(r.point_volume);
      p.half_size.emplace_back(5e-4, 5e-4, 5e-4);
      p.body.push_back(i < 3 ? 1 : i < 3 + r.deformable_points ? 0 : 2);
    }
    auto metres = [](double v) {
      char t[64];
      std::snprintf(t, sizeof t, "%.17g m", v);
      return std::string(t);
    };
    p.parameters = {{"cell", r.cell},
                    {"strut_diameter", metres(r.strut_diameter)},
                    {"strut_length", metres(r.strut_length)},
                    {"lattice_zmin", metres(r.lattice_zmin)},
                    {"lattice_zmax", metres(r.lattice_zmax)}};
    if (r.footprint_area > 0) {
      char area[64];
      std::snprintf(area, sizeof area, "%.17g m^2", r.footprint_area);
      p.parameters["footprint_area"] = area;
    }
    Hdf5File f(points_file, Hdf5File::Mode::create);
    write_point_set(f, p);
    write_provenance(f, Provenance{"synthetic_run", "test", "write_synthetic_run()", {}, "2024-01-01T00:00:00Z", {}});
  }
  char e[64], rho[64];
  std::snprintf(e, sizeof e, "%.17gPa", r.youngs_modulus);
  std::snprintf(rho, sizeof rho, "%.17gkg/m^3", r.density);
  std::ofstream(fs::path(dir) / "scene.toml")
      << "# Resolved scene written by a test\n[run]\nend = { plate_displacement = '20mm' }\n"
      << "[time]\nmass_scaling = 6\n"
      << "[bodies.lattice]\nrole = 'deformable'\nmaterial = { E = '" << e << "', nu = 0.4, density = '" << rho << "' }\n"
      << "[bodies.bottom_plate]\nrole = 'fixed'\n[bodies.top_plate]\nrole = 'driven'\n"
      << "velocity = ['0mm/s', '0mm/s', '-100mm/s']\n[[points]]\nfile = '" << points_file << "'\n";
  std::ofstream log(fs::path(dir) / "log.txt");
  log << "[     0.0s] latmpm-solve test\n";
  if (r.status == "failed") log << "[     1.0s] stopped: numerical failure: step 42: particle 7 inverted\n";
  if (!r.status.empty()) log << "[     1.0s] status: " << r.status << " steps=100 time=0.1 wall_s=1\n";
  std::ofstream(fs::path(dir) / "series.csv") << series_csv_text(series);
}

}  // namespace latmpm::test
