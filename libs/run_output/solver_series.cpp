#include "run_output/solver_series.hpp"

#include "mpm/particle_fields.hpp"

namespace latmpm {

std::vector<SeriesColumn> solver_series_columns(bool with_flyer) {
  std::vector<SeriesColumn> columns = {
      {"step", "1", "steps completed"},
      {"time", "s", "simulated time at the end of the step"},
      {"dt", "s", "time step of the step"},
      {"displacement", "m", "driven body's travel along the loading axis"},
      {"load_driven", "N", "reaction on the driven bodies along the loading axis, compression positive"},
      {"load_fixed", "N",
       "reaction on the fixed point and rigid bodies and held points against the loading axis, compression positive"},
      {"load_record", "N", "record layer: -(mean vertical stress) x area (Paper A Sec. 5.1), compression positive"},
      {"kinetic_energy", "J", "1/2 sum m v^2 over deformable points"},
      {"strain_energy", "J", "sum V0 psi over deformable points"},
      {"external_work", "J", "work of the driven bodies (penalty bodies: f.V on their contact springs) and gravity since the start"},
      {"max_speed", "m/s", "largest particle speed of deformable points"},
      {"constraint_work", "J", "work of the fixed and driven point bodies' reactions (zero for a fixed base)"},
      {"gravity_work", "J", "work of gravity on the deformable material"},
      {"energy_error", "J",
       "kinetic + strain + plastic dissipation + flyer energy + contact energy + friction dissipation + blend "
       "dissipation + transfer dissipation - initial - constraint_work - gravity_work - driven rigid bodies' work"},
      {"plastic_dissipation", "J", "plastic work of the J2 points since the start, sum V0 x j2_plastic_work"},
      {"contact_energy", "J", "energy held in the penalty bodies' contact springs, sum |f|^2 / (2 kappa)"},
      {"friction_dissipation", "J", "energy dissipated by the penalty bodies' Coulomb friction since the start"},
      {"load_average", "N",
       "-A0 x current-volume average of the stress along the loading axis over the deformable material, A0 = "
       "V0 / l0 (paper B Eq. 14, f_a), compression positive"},
      {"blend_dissipation", "J",
       "kinetic energy the FLIP/PIC velocity blend removed since the start, sum 1/2 m (|v_FLIP|^2 - |v|^2) (numerical)"},
      {"grid_contact_dissipation", "J",
       "kinetic energy grid contact ([contact]) took out of its contact nodes since the start, sum 1/2 m_K (|v*_K|^2 - "
       "|v_K|^2): a nodal estimate, not in energy_error (it overcounts the points' loss, docs/contact.md)"},
      {"transfer_dissipation", "J",
       "energy the FLIP update's grid-to-point projection lost since the start, sum m_I |dv_I|^2 - sum m_p "
       "|dv_p|^2 over steps (numerical)"},
  };
  if (with_flyer) {
    const std::vector<SeriesColumn> flyer = {
        {"load_flyer", "N", "contact force on the free rigid bodies along the loading axis, compression positive"},
        {"flyer_velocity", "m/s", "velocity of the first free rigid body along the loading axis"},
        {"flyer_displacement", "m", "travel of the first free rigid body along the loading axis"},
        {"flyer_kinetic_energy", "J", "1/2 M V^2 of the first free rigid body"},
        {"flyer_potential_energy", "J", "-M g.(X - X0) of the first free rigid body"},
    };
    columns.insert(columns.end(), flyer.begin(), flyer.end());
  }
  return columns;
}

bool has_flyer(const mpm::Simulation& sim) {
  for (const auto& r : sim.boundary_reports())
    if (r.role == mpm::BoundaryRole::free) return true;
  return false;
}

std::vector<double> SolverSeries::row(const mpm::Simulation& sim, const mpm::StepDiagnostics& d) const {
  const Eigen::Vector3d& axis = axis_;
  // One pass over the boundaries (point-defined ones first, then the rigid bodies): driven
  // ones load the specimen and the first gives the displacement, fixed ones and held points
  // hold it up, free ones are flyers.
  double displacement = 0, load_driven = 0, load_fixed = 0, load_flyer = 0;
  bool displacement_taken = false;
  const mpm::BoundaryReport* flyer = nullptr;
  const auto reports = sim.boundary_reports();
  for (const auto& r : reports) {
    const double along = Eigen::Vector3d(r.reaction).dot(axis);
    switch (r.role) {
      case mpm::BoundaryRole::driven:
        load_driven += along;
        if (!displacement_taken) displacement = Eigen::Vector3d(r.displacement).dot(axis);
        displacement_taken = true;
        break;
      case mpm::BoundaryRole::fixed:
      case mpm::BoundaryRole::held: load_fixed = load_fixed - along; break;
      case mpm::BoundaryRole::free:
        load_flyer += along;
        if (!flyer) flyer = &r;
        break;
    }
  }
  std::vector<double> row = {double(d.step),   d.time,           d.dt,
                             displacement,     load_driven,      load_fixed,
                             0.0 - record_(sim),  d.kinetic_energy, d.strain_energy,  // 0 - x: no "-0"
                             d.external_work,  d.max_speed,      d.constraint_work,
                             d.gravity_work,   d.energy_error,   d.plastic_dissipation,
                             d.contact_energy, d.friction_dissipation, 0.0 - average_(sim),
                             d.blend_dissipation, d.grid_contact_dissipation, d.transfer_dissipation};
  if (flyer)
    row.insert(row.end(), {0.0 + load_flyer, 0.0 + Eigen::Vector3d(flyer->velocity).dot(axis),
                           0.0 + Eigen::Vector3d(flyer->displacement).dot(axis), flyer->kinetic_energy,
                           0.0 + flyer->potential_energy});
  return row;
}

ParticleSnapshot solver_snapshot(const mpm::Simulation& sim) { return solver_snapshot(sim, sim.particles()); }

ParticleSnapshot solver_snapshot(const mpm::Simulation& sim, const mpm::Particles& p, size_t first_id) {
  const size_t n = p.size();
  ParticleSnapshot s;
  s.step = sim.step_count();
  s.time = sim.time();
  s.resize(n);
  for (const auto& b : sim.bodies()) s.body_names.push_back(b.name);
  // Voigt (xx yy zz yz xz xy) to XDMF Tensor6 (xx xy xz yy yz zz).
  constexpr int tensor6_from_voigt[6] = {0, 5, 4, 1, 3, 2};
  for (size_t q = 0; q < n; ++q) {
    const size_t i = p.id[q] - first_id;
    for (int k = 0; k < 3; ++k) {
      s.position[3 * i + k] = p.position[q][k];
      s.velocity[3 * i + k] = float(p.velocity[q][k]);
    }
    for (int k = 0; k < 6; ++k) s.stress[6 * i + k] = float(p.stress[q][tensor6_from_voigt[k]]);
    s.von_mises[i] = float(p.von_mises_stress(q));
    s.jacobian[i] = float(p.jacobian(q));
    s.body[i] = p.body[q];
  }
  // The registry's snapshot fields beyond the fixed ones: the material history columns.
  mpm::for_each_particle_field(p, [&](const mpm::ParticleField& field, const auto& values, const auto&) {
    if constexpr (std::is_same_v<std::decay_t<decltype(values)>, std::vector<mpm::Real>>) {
      if (!field.snapshot) return;
      ParticleSnapshot::Scalar scalar{field.name, std::vector<float>(n)};
      for (size_t q = 0; q < n; ++q) scalar.values[p.id[q] - first_id] = float(values[q]);
      s.extra_scalars.push_back(std::move(scalar));
    }
  });
  return s;
}

}  // namespace latmpm
