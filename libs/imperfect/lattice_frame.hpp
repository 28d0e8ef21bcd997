// Where the parts of a printed lattice lie in a point set: the bases, the lattice between
// them and its cell layers. The perturbations of paper A Sec. 5.3 (types A–D) are defined on
// these heights (docs/imperfections.md).
//
// Values come from the source geometry's parameters that the voxelizer copies into the point
// set (`lattice_zmin`, `lattice_zmax`, `layer_height`, `cells`); when a parameter is absent
// the frame falls back to body extents (the plates' faces) and says so in `notes`.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "points/point_set.hpp"

namespace latmpm {

// Axis-aligned extent of a set of points including their GIMP particle domains (x ± half
// size), i.e. the region of space the material occupies. Lengths in m.
struct Extent {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(1e300);
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-1e300);
  bool empty() const { return min.x() > max.x(); }
  void add(const Eigen::Vector3d& centre, const Eigen::Vector3d& half) {
    min = min.cwiseMin(centre - half);
    max = max.cwiseMax(centre + half);
  }
};

// Extent of the points whose body is in `bodies` (body indices).
Extent body_extent(const PointSet& points, const std::vector<int>& bodies);

struct LatticeFrame {
  double lattice_zmin = 0;  // m, bottom of the struts = top face of the bottom base
  double lattice_zmax = 0;  // m, top of the struts = bottom face of the top base
  double layer_height = 0;  // m, height of one cell layer; 0 when unknown
  std::vector<std::string> notes;  // which values were not found in the parameters, and why
};

// Reads the frame of `points`; `where` names the file for messages. `layer_height_override`
// (> 0) replaces the file's value (the --layer-height option). Throws InputError when a
// parameter is present but malformed, or when the lattice heights cannot be found at all.
LatticeFrame find_lattice_frame(const PointSet& points, const std::string& where,
                                double layer_height_override = 0);

}  // namespace latmpm
