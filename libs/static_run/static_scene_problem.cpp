#include "static_run/static_scene_problem.hpp"

#include <algorithm>
#include <limits>

#include "core/errors.hpp"
#include "mpm/material.hpp"
#include "mpm/rigid_body.hpp"
#include "mpm/shape_function_kind.hpp"
#include "run_output/scene_simulation.hpp"

namespace latmpm {

namespace {
// The static solver has energies for the elastic models only (statics/elastic_energy.hpp):
// a model with history (J2) has no potential to minimise, so it is refused, not replaced.
mpm::MaterialParameters static_material(const BodySpec& body) {
  const std::string field = "bodies." + body.name + ".material";
  const mpm::MaterialParameters& p = body.material;
  if (p.kind != mpm::MaterialKind::linear_elastic && p.kind != mpm::MaterialKind::neo_hookean)
    throw InputError(body.where, field + ".model",
                     std::string("the static solver has no energy for \"") + to_string(p.kind) +
                         "\" (linear_elastic or neo_hookean)");
  return p;
}
}  // namespace

StaticSceneProblem make_static_problem(const Scene& scene, const PointSet& points) {
  for (const RigidBodySpec& r : scene.rigid_bodies)
    if (r.motion == mpm::RigidMotion::free || r.motion == mpm::RigidMotion::scheduled)
      throw InputError(r.where, "rigid_bodies." + r.name + ".motion",
                       "the static solver has no " + mpm::to_string(r.motion) +
                           " bodies (one monotonic load path): use driven or fixed");
  StaticSceneProblem out;
  out.half_size.resize(points.size());
  for (size_t p = 0; p < points.size(); ++p) out.half_size[p] = points.domain_half_size(p);
  // Material points and their energies (one per deformable body).
  std::vector<statics::Vec3> X, half;
  std::vector<statics::Real> volume;
  std::vector<uint16_t> material;
  std::vector<statics::ElasticEnergy> energies;
  std::vector<int> energy_of_body(scene.bodies.size(), -1);
  const BodySpec* driven = nullptr;
  const RigidBodySpec* driven_rigid = nullptr;
  for (const RigidBodySpec& r : scene.rigid_bodies)
    if (r.motion == mpm::RigidMotion::driven) driven_rigid = &r;
  for (size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodySpec& body = scene.bodies[b];
    if (body.role == BodyRole::deformable) {
      energy_of_body[b] = int(energies.size());
      energies.push_back(statics::ElasticEnergy::from(static_material(body)));
    } else if (body.role == BodyRole::driven) {
      if (driven) throw InputError(body.where, "bodies." + body.name + ".role", "the static solver drives one body");
      driven = &body;
    }
  }
  if (bool(driven) + bool(driven_rigid) != 1)
    throw InputError(scene.solver.where, "solver.kind", "a static solve needs exactly one driven body (the platen)");
  for (size_t p = 0; p < points.size(); ++p) {
    const int e = energy_of_body[size_t(points.body[p])];
    if (e < 0) continue;
    out.material_points.push_back(p);
    X.push_back(points.position[p]);
    half.push_back(out.half_size[p]);
    volume.push_back(points.volume[p]);
    material.push_back(uint16_t(e));
  }
  const double h = scene.settings.cell_size;
  out.problem = std::make_unique<statics::StaticProblem>(statics::build_narrow_band(X, half, h, scene.settings.shape_function),
                                                         std::move(volume), std::move(material), std::move(energies));

  // Supports and platen: the band nodes their points reach.
  std::vector<statics::Vec3> support_x, support_half, platen_x, platen_half;
  for (size_t p = 0; p < points.size(); ++p) {
    const BodySpec& body = scene.bodies[size_t(points.body[p])];
    bool held = false;
    if (!body.hold_tag.empty()) {
      auto tag = points.tags.find(body.hold_tag);
      held = tag != points.tags.end() && tag->second[p];
    }
    if (body.role == BodyRole::fixed || held) support_x.push_back(points.position[p]), support_half.push_back(out.half_size[p]);
    if (body.role == BodyRole::driven) platen_x.push_back(points.position[p]), platen_half.push_back(out.half_size[p]);
  }
  const statics::NarrowBand& band = out.problem->band();
  out.loading.support_nodes = statics::nodes_reached_by(band, support_x, support_half);
  out.loading.platen_nodes = statics::nodes_reached_by(band, platen_x, platen_half);
  // Rigid bodies by geometry: the band nodes the explicit solver couples to them, those whose
  // support (the open cube of half-width h) overlaps the body (mpm::rigid_body_contains), so
  // that both solvers hold the same nodes (bonded: the static counterpart of the no-slip grid
  // coupling). A half-space short of every such node is first moved into contact (the
  // explicit run's travel before its first contact).
  for (const RigidBodySpec& r : scene.rigid_bodies) {
    auto& nodes = r.motion == mpm::RigidMotion::driven ? out.loading.platen_nodes : out.loading.support_nodes;
    Eigen::Vector3d contact = Eigen::Vector3d::Zero();
    if (r.shape == mpm::RigidShape::half_space) {
      const Eigen::Vector3d n = r.plane_normal.normalized();
      double gap = std::numeric_limits<double>::infinity();
      for (size_t i = 0; i < band.node_count(); ++i) gap = std::min(gap, (band.node_position(i) - r.plane_point).dot(n) - h);
      gap = std::max(gap, 0.0);
      out.contact_gap = std::max(out.contact_gap, gap);
      if (gap > 0) contact = (gap + 1e-6 * h) * n;  // just past touching: the open cube overlaps
    }
    for (size_t i = 0; i < band.node_count(); ++i)
      if (mpm::rigid_body_contains(r, contact, band.node_position(i), h)) nodes.push_back(i);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  }
  const std::string driven_where = driven ? driven->where : driven_rigid->where;
  if (out.loading.platen_nodes.empty())
    throw InputError(driven_where, "driven body", "the driven body touches no node of the material");
  if (out.loading.support_nodes.empty())
    throw InputError(scene.solver.where, "solver.kind", "a static solve needs a support: a fixed body or held points");
  out.loading.direction = (driven ? driven->velocity : driven_rigid->velocity).normalized();
  out.loading.travel = scene.end.value;
  out.loading.increments = scene.solver.statics.increments;
  out.loading.check_stability = scene.solver.statics.check_stability;
  out.loading.predictor = scene.solver.statics.predictor;
  out.loading.max_step_growth = scene.solver.statics.max_increment_growth;
  out.loading.bisections = scene.solver.statics.bisections;
  out.problem->set_stabilisation(scene.solver.statics.stabilisation);
  return out;
}

}  // namespace latmpm
