// The closed set of constitutive models and the one place that dispatches over them.
// Adding a model: one header like linear_elastic.hpp, one alternative here, one case in
// make_material_model.
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
