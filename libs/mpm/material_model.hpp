// The closed set of constitutive models and the one place that dispatches over them.
// Adding a model: one header like linear_elastic.hpp, one alternative here, one case in
// make_material_model. A model provides update_stress(Deformation, stress),
// strain_energy_density(F, J, stress) (J/m³ of reference volume) and
// wave_speed_squared(J) (m²/s², non-increasing in J: the solver evaluates it at the
// smallest J of each body run).
#pragma once
#include <variant>

#include "mpm/linear_elastic.hpp"
#include "mpm/neo_hookean.hpp"

namespace latmpm::mpm {

using MaterialModel = std::variant<LinearElastic, NeoHookean>;

inline MaterialModel make_material_model(const MaterialParameters& m, Real mass_scaling) {
  switch (m.kind) {
    case MaterialKind::linear_elastic: return LinearElastic::from(m, mass_scaling);
    case MaterialKind::neo_hookean: return NeoHookean::from(m, mass_scaling);
  }
  return LinearElastic::from(m, mass_scaling);
}

}  // namespace latmpm::mpm
