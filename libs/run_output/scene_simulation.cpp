#include "run_output/scene_simulation.hpp"

#include "core/errors.hpp"
#include "mpm/material.hpp"
#include "mpm/rigid_body.hpp"

namespace latmpm {

mpm::Settings solver_settings(const Scene& scene, int threads) {
  mpm::Settings s = scene.settings;
  s.threads = threads;
  mpm::validate(s, scene.where);
  return s;
}

std::vector<mpm::BodySettings> solver_bodies(const Scene& scene) {
  const mpm::MaterialParameters* fallback = nullptr;
  for (const auto& b : scene.bodies)
    if (b.role == BodyRole::deformable && !fallback) fallback = &b.material;
  std::vector<mpm::BodySettings> bodies;
  for (const auto& b : scene.bodies) {
    mpm::BodySettings s = b;
    if (!b.has_material) {
      if (!fallback)
        throw InputError(b.where, "bodies." + b.name + ".material",
                         "the scene has no deformable body to take a density from; give this body a material");
      s.material = *fallback;
    }
    bodies.push_back(s);
  }
  return bodies;
}

std::vector<mpm::RigidBodySettings> solver_rigid_bodies(const Scene& scene) {
  std::vector<mpm::RigidBodySettings> out;
  for (const auto& r : scene.rigid_bodies) {
    mpm::validate(r, r.where);
    out.push_back(r);
  }
  return out;
}

Eigen::Vector3d loading_axis(const Scene& scene) {
  for (const auto& b : scene.bodies)
    if (b.role == BodyRole::driven) return b.velocity.normalized();
  for (const auto& r : scene.rigid_bodies)
    if (r.motion == mpm::RigidMotion::driven) return r.velocity.normalized();
  for (const auto& r : scene.rigid_bodies)
    if (r.motion == mpm::RigidMotion::scheduled && r.schedule.max_speed() > 0) return r.schedule.first_direction();
  for (const auto& r : scene.rigid_bodies)
    if (r.motion == mpm::RigidMotion::free && r.velocity.norm() > 0) return r.velocity.normalized();
  if (scene.settings.gravity.norm() > 0) return scene.settings.gravity.normalized();
  return Eigen::Vector3d(0, 0, -1);
}

double end_time(const Scene& scene) {
  if (scene.end.kind == EndCondition::time) return scene.end.value;
  for (const auto& b : scene.bodies)
    if (b.role == BodyRole::driven) return scene.end.value / b.velocity.norm();
  for (const auto& r : scene.rigid_bodies)
    if (r.motion == mpm::RigidMotion::driven) return scene.end.value / r.velocity.norm();
  throw InputError(scene.end.where, "run.end.plate_displacement", "needs a driven body");
}

}  // namespace latmpm
