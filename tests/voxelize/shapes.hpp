// Analytic solids for the voxelizer tests: a level set made by OpenVDB or the strut-graph
// rasteriser, the exact signed distance and the exact volume.
#pragma once
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <cmath>
#include <string>

#include "geometry/strut_graph.hpp"
#include "levelset/level_set_units.hpp"
#include "levelset/solid_primitive.hpp"
#include "levelset/strut_level_set.hpp"

namespace latmpm::test {

struct AnalyticSolid {
  std::string name;
  SolidPrimitive::Kind kind;
  Eigen::Vector3d a, b;  // sphere: a = centre; capsule/cylinder: axis ends; box: corners
  double radius = 0;

  double distance(const Eigen::Vector3d& p) const {
    if (name == "sphere") return (p - a).norm() - radius;
    return SolidPrimitive{kind, a, b, radius}.distance(p);
  }
  double volume() const {
    const double pi = M_PI;
    if (name == "sphere") return 4.0 / 3.0 * pi * std::pow(radius, 3);
    if (kind == SolidPrimitive::Kind::box) return (b - a).prod();
    const double l = (b - a).norm();
    if (kind == SolidPrimitive::Kind::cylinder) return pi * radius * radius * l;
    return pi * radius * radius * l + 4.0 / 3.0 * pi * std::pow(radius, 3);
  }
  StrutGraph graph() const {
    StrutGraph g;
    g.name = name;
    if (kind == SolidPrimitive::Kind::box) {
      g.plates.push_back({"block", a, b});
    } else {
      g.nodes = {a, b};
      g.struts.push_back({0, 1, radius});
      g.strut_ends = kind == SolidPrimitive::Kind::cylinder ? StrutEnds::flat : StrutEnds::round;
    }
    return g;
  }
  openvdb::FloatGrid::Ptr level_set(double voxel, double half_width) const {
    if (name == "sphere")
    {
      const double k = grid_units_per_metre;  // grids are in millimetres
      return openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
          float(k * radius), openvdb::Vec3f(float(k * a.x()), float(k * a.y()), float(k * a.z())), float(k * voxel),
          float(half_width));
    }
    return strut_graph_level_set(graph(), voxel, half_width);
  }
};

// A solid of characteristic radius r (sphere radius, strut radius, box half-edge) near `c`.
inline AnalyticSolid analytic_solid(const std::string& name, double r, const Eigen::Vector3d& c) {
  using K = SolidPrimitive::Kind;
  if (name == "sphere") return {name, K::capsule, c, c, r};
  if (name == "box") return {name, K::box, c - Eigen::Vector3d(r, 1.3 * r, 0.8 * r), c + Eigen::Vector3d(r, 1.3 * r, 0.8 * r), 0};
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 1.0).normalized() * 3.0 * r;
  if (name == "capsule") return {name, K::capsule, c - axis, c + axis, r};
  return {name, K::cylinder, c - axis, c + axis, r};
}

}  // namespace latmpm::test
