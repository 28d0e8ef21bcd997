// Supports and loads of an optimisation problem, in world units so that the same load case
// applies on the optimisation grid and on the refined evaluation grid (paper C Sec. 4.2).
//   support: grid nodes inside a box are held (per component);
//   load: a total force spread equally over the quadrature points inside a box (the paper's
//         nodal loads become loads on the points around the node: the static solver takes
//         point forces, and points keep the load on material at every resolution).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "optimize/design_grid.hpp"

namespace latmpm::optimize {

struct Box {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // m
  bool contains(const Vec3& x) const { return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all(); }
};

struct Support {
  Box box;
  std::array<bool, 3> held{true, true, true};  // x, y, z components
  std::string name;
};

struct Load {
  Box box;
  Vec3 force = Vec3::Zero();  // total, N
  std::string name;
};

struct LoadCase {
  std::vector<Support> supports;
  std::vector<Load> loads;
};

// A plane of mirror symmetry the scene models by holding one displacement component on a
// face of the design domain (paper C's half models: z = 0 of the 3D beam): the part is the
// design mirrored through it.
struct SymmetryPlane {
  int axis = 0;               // its normal
  bool far_face = false;      // x_axis = extent (else x_axis = 0)
};

// The supports that hold exactly one component on nodes of one domain face, normal to it.
std::vector<SymmetryPlane> symmetry_planes(const DesignGrid& grid, const LoadCase& load_case);

// Points of `grid` inside each load's box (one list per load).
std::vector<std::vector<size_t>> loaded_points(const DesignGrid& grid, const LoadCase& load_case);

}  // namespace latmpm::optimize
