// The closed set of constitutive models and the one place that dispatches over them.
// Adding a model: one header like linear_elastic.hpp, one alternative here, one case in
// make_material_model. A model with per-particle history declares it once
// (material_history.hpp); the particle columns, sorting and checkpoints follow. A model provides, as templates over T = Real or Pack,
// update_stress(Deformation<T>, Stress<T>&) and strain_energy_density(Deformation<T>,
// Stress<T>) (J/m³ of reference volume), and wave_speed_squared(J) (m²/s², non-increasing
// in J: the solver evaluates it at the smallest J of each body run).
#pragma once
#include <algorithm>
#include <array>
#include <variant>

#include "mpm/j2_material.hpp"
#include "mpm/linear_elastic.hpp"
#include "mpm/material_history.hpp"
#include "mpm/neo_hookean.hpp"

namespace latmpm::mpm {

using MaterialModel = std::variant<LinearElastic, NeoHookean, J2Plastic>;

inline MaterialModel make_material_model(const MaterialParameters& m, Real mass_scaling) {
  switch (m.kind) {
    case MaterialKind::linear_elastic: return LinearElastic::from(m, mass_scaling);
    case MaterialKind::neo_hookean: return NeoHookean::from(m, mass_scaling);
    case MaterialKind::j2: return J2Plastic::from(m, mass_scaling);
  }
  return LinearElastic::from(m, mass_scaling);
}

// A particle's history variables at the start of a run (at least one slot, so that
// .data() is never null).
template <class Model>
std::array<Real, std::max<size_t>(history_size<Model>, 1)> initial_history() {
  std::array<Real, std::max<size_t>(history_size<Model>, 1)> values{};
  for (size_t k = 0; k < history_size<Model>; ++k) values[k] = material_history<Model>::variables[k].initial;
  return values;
}

// One particle with Eigen types (set-up, tests): the stress after a step, and ψ per
// reference volume for the deformation F and stress s. `history`: the particle's history
// variables (material_history.hpp), updated in place; unused by models without history;
// null: updated_stress starts from the initial values (and discards them), the energy takes
// those of a point set up in that state (the derived ones from F and s, as the solver sets
// them before the first step).
template <class Model>
SymTensor updated_stress(const Model& model, const Mat3& L, const Mat3& F_new, Real dt, const SymTensor& s,
                         Real* history = nullptr) {
  const Deformation<Real> d = make_deformation(L, F_new, dt);
  Real out[6];
  for (int c = 0; c < 6; ++c) out[c] = s[c];
  auto initial = initial_history<Model>();
  update_material_stress(model, d, out, history ? history : initial.data());
  SymTensor result;
  for (int c = 0; c < 6; ++c) result[c] = out[c];
  return result;
}

template <class Model>
Real strain_energy_density(const Model& model, const Mat3& F, const SymTensor& s, const Real* history = nullptr) {
  const Deformation<Real> d = make_deformation(Mat3::Zero(), F, 0);
  Real stress[6];
  for (int c = 0; c < 6; ++c) stress[c] = s[c];
  auto set_up = initial_history<Model>();
  if constexpr (derives_history<Model>::value)
    if (!history) model.history_from_state(d, stress, set_up.data());
  return material_energy_density(model, d, stress, history ? history : set_up.data());
}

}  // namespace latmpm::mpm
