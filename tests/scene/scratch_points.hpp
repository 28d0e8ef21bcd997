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

}  // namespace latmpm::test
