// A scratch directory holding one point file (`pts.h5`, one point of body "column") that the
// scene-reader tests' scenes can name; made once per test process.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/hdf5_file.hpp"
#include "points/point_set.hpp"
#include "scratch_dir.hpp"

namespace latmpm::test {

inline std::string scratch_points_dir(const std::string& label) {
  namespace fs = std::filesystem;
  const fs::path d = process_scratch(label).path();
  PointSet p;
  p.position = {{0, 0, 0}};
  p.volume = {1e-9};
  p.body = {0};
  p.half_size = {{5e-4, 5e-4, 5e-4}};
  p.body_names = {"column"};
  p.cell_size = 1e-3;
  p.ppc = 1;
  Hdf5File f((d / "pts.h5").string(), Hdf5File::Mode::create);
  write_point_set(f, p);
  return d.string();
}

// Lines 1-9 of a test scene over that file: the run's end (line 2's table), a 1 mm grid and the
// deformable body "column"; the caller adds its plate from line 10 on.
inline std::string column_scene_head(const std::string& end) {
  return "[run]\n"                                                             // 1
         "end = " + end + "\n" +                                               // 2
         "[grid]\n"                                                            // 3
         "cell = \"1mm\"\n"                                                    // 4
         "[[points]]\n"                                                        // 5
         "file = \"pts.h5\"\n"                                                 // 6
         "[bodies.column]\n"                                                   // 7
         "role = \"deformable\"\n"                                             // 8
         "material = { E = \"10MPa\", nu = 0.4, density = \"1050kg/m^3\" }\n";  // 9
}

}  // namespace latmpm::test
