#include "scene/driven_body_reach.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

namespace latmpm {
namespace {

// The travel of a driven body moving at `speed` (m/s) over the run.
double travel(const Scene& scene, double speed) {
  return scene.end.kind == EndCondition::plate_displacement ? scene.end.value : speed * scene.end.value;
}

Eigen::AlignedBox3d swept(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& shift, double grow) {
  Eigen::AlignedBox3d out = box;
  out.extend(box.min() + shift);
  out.extend(box.max() + shift);
  out.min().array() -= grow;
  out.max().array() += grow;
  return out;
}

double box_gap(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b) {
  const Eigen::Vector3d apart = (a.min() - b.max()).cwiseMax(b.min() - a.max()).cwiseMax(0.0);
  return apart.norm();
}

std::string warning(const std::string& where, const std::string& name, double distance, double gap) {
  char text[400];
  std::snprintf(text, sizeof text,
                "warning: %s: the driven body '%s' never comes within a cell of a deformable body in its "
                "%.4g mm of travel (%.4g mm away at the start): the load will stay zero; is the part "
                "standing on the platen (latmpm-voxelize --place, --stand-on)?",
                where.c_str(), name.c_str(), distance * 1e3, gap * 1e3);
  return text;
}

}  // namespace

std::vector<std::string> driven_body_warnings(const Scene& scene, const PointSet& points) {
  std::vector<std::string> out;
  // The deformable points' sub-cells.
  std::vector<Eigen::AlignedBox3d> material;
  for (size_t i = 0; i < points.size(); ++i) {
    const auto b = static_cast<size_t>(points.body[i]);
    if (b < scene.bodies.size() && scene.bodies[b].role == BodyRole::deformable)
      material.emplace_back(points.position[i] - points.half_size[i], points.position[i] + points.half_size[i]);
  }
  if (material.empty()) return out;
  const double h = scene.settings.cell_size > 0 ? scene.settings.cell_size : points.cell_size;
  auto check_box = [&](const Eigen::AlignedBox3d& body, const Eigen::Vector3d& velocity, const std::string& where,
                       const std::string& name) {
    const double distance = travel(scene, velocity.norm());
    const Eigen::AlignedBox3d reach = swept(body, distance * velocity.normalized(), h);
    double gap = INFINITY;
    for (const auto& m : material) {
      if (reach.intersects(m)) return;
      gap = std::min(gap, box_gap(body, m));
    }
    out.push_back(warning(where, name, distance, gap));
  };
  for (size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodySpec& body = scene.bodies[b];
    if (body.role != BodyRole::driven || body.velocity.norm() == 0) continue;
    Eigen::AlignedBox3d box;
    for (size_t i = 0; i < points.size(); ++i)
      if (static_cast<size_t>(points.body[i]) == b) {
        box.extend(points.position[i] - points.half_size[i]);
        box.extend(points.position[i] + points.half_size[i]);
      }
    if (!box.isEmpty()) check_box(box, body.velocity, body.where, body.name);
  }
  for (const RigidBodySpec& r : scene.rigid_bodies) {
    if (r.motion != mpm::RigidMotion::driven || r.velocity.norm() == 0) continue;
    if (r.shape == mpm::RigidShape::box) {
      check_box(Eigen::AlignedBox3d(r.box_min, r.box_max), r.velocity, r.where, r.name);
      continue;
    }
    // Half-space {(x − p)·n ≤ 0} moved by the travel: some material must come within a cell.
    const Eigen::Vector3d n = r.plane_normal;
    const double advance = travel(scene, r.velocity.norm()) * r.velocity.normalized().dot(n);
    double gap = INFINITY;
    for (const auto& m : material) {
      // The sub-cell's corner deepest toward the body.
      Eigen::Vector3d corner;
      for (int a = 0; a < 3; ++a) corner[a] = n[a] > 0 ? m.min()[a] : m.max()[a];
      gap = std::min(gap, (corner - r.plane_point).dot(n));
    }
    if (gap > advance + h) out.push_back(warning(r.where, r.name, travel(scene, r.velocity.norm()), gap));
  }
  return out;
}

}  // namespace latmpm
