#include "run_output/scene_simulation.hpp"

#include "core/errors.hpp"
#include "mpm/material.hpp"
#include "mpm/rigid_body.hpp"
#include "mpm/shape_function_kind.hpp"

namespace latmpm {

mpm::Settings solver_settings(const Scene& scene, int threads) {
  mpm::Settings s;
  s.cell_size = scene.cell_size;
  s.shape_function = scene.shape;
  s.scheme = scene.scheme;
  s.flip_blend = scene.flip;
  s.ddmp_alpha_peak = scene.ddmp_alpha_peak;
  s.ddmp_alpha_exponent = scene.ddmp_alpha_exponent;
  s.ddmp_on_grid = scene.ddmp_on_grid;
  s.cfl = scene.cfl;
  s.fixed_time_step = scene.dt;
  s.mass_scaling = scene.mass_scaling;
  s.gravity = scene.gravity;
  s.record_tag = scene.record_tag;
  s.threads = threads;
  mpm::validate(s, scene.where);
  return s;
}

mpm::MaterialParameters solver_material(const MaterialSpec& m) {
  mpm::MaterialParameters p;
  p.kind = m.model;
  p.young_modulus = m.youngs_modulus;
  p.poisson_ratio = m.poisson_ratio;
  p.density = m.density;
  p.initial_yield = m.initial_yield;
  p.saturation_yield = m.saturation_yield;
  p.saturation_rate = m.saturation_rate;
  p.linear_hardening = m.linear_hardening;
  return p;
}

std::vector<mpm::BodySettings> solver_bodies(const Scene& scene) {
  const MaterialSpec* fallback = nullptr;
  for (const auto& b : scene.bodies)
    if (b.role == BodyRole::deformable && !fallback) fallback = &b.material;
  std::vector<mpm::BodySettings> bodies;
  for (const auto& b : scene.bodies) {
    mpm::BodySettings s;
    s.name = b.name;
    s.role = mpm::parse_body_role(to_string(b.role), b.where, "bodies." + b.name + ".role");
    const MaterialSpec* m = b.has_material ? &b.material : fallback;
    if (!m)
      throw InputError(b.where, "bodies." + b.name + ".material",
                       "the scene has no deformable body to take a density from; give this body a material");
    s.material = solver_material(*m);
    s.velocity = b.velocity;
    s.hold_tag = b.hold_tag;
    s.hold_slip = b.hold_slip;
    bodies.push_back(s);
  }
  return bodies;
}

std::vector<mpm::RigidBodySettings> solver_rigid_bodies(const Scene& scene) {
  std::vector<mpm::RigidBodySettings> out;
  for (const auto& r : scene.rigid_bodies) {
    mpm::RigidBodySettings b;
    b.name = r.name;
    b.shape = r.shape == RigidBodySpec::box ? mpm::RigidShape::box : mpm::RigidShape::half_space;
    b.box_min = r.min;
    b.box_max = r.max;
    b.plane_point = r.point;
    b.plane_normal = r.normal.normalized();
    b.motion = r.motion == RigidBodySpec::driven ? mpm::RigidMotion::driven
               : r.motion == RigidBodySpec::free ? mpm::RigidMotion::free
                                                 : mpm::RigidMotion::fixed;
    b.velocity = r.velocity;
    b.mass = r.mass;
    b.gravity = r.gravity;
    b.coupling = r.contact == RigidBodySpec::penalty ? mpm::RigidCoupling::penalty : mpm::RigidCoupling::no_slip;
    b.friction = r.friction;
    b.contact_stiffness = r.contact_stiffness;
    mpm::validate(b, r.where);
    out.push_back(b);
  }
  return out;
}

Eigen::Vector3d loading_axis(const Scene& scene) {
  for (const auto& b : scene.bodies)
    if (b.role == BodyRole::driven) return b.velocity.normalized();
  for (const auto& r : scene.rigid_bodies)
    if (r.motion == RigidBodySpec::driven) return r.velocity.normalized();
  for (const auto& r : scene.rigid_bodies)
    if (r.motion == RigidBodySpec::free && r.velocity.norm() > 0) return r.velocity.normalized();
  if (scene.gravity.norm() > 0) return scene.gravity.normalized();
  return Eigen::Vector3d(0, 0, -1);
}

double end_time(const Scene& scene) {
  if (scene.end.kind == EndCondition::time) return scene.end.value;
  for (const auto& b : scene.bodies)
    if (b.role == BodyRole::driven) return scene.end.value / b.velocity.norm();
  for (const auto& r : scene.rigid_bodies)
    if (r.motion == RigidBodySpec::driven) return scene.end.value / r.velocity.norm();
  throw InputError(scene.end.where, "run.end.plate_displacement", "needs a driven body");
}

}  // namespace latmpm
