#include "mpm/material.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "mpm/j2_plasticity.hpp"

namespace latmpm::mpm {

Real MaterialParameters::lame_lambda() const {
  return young_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio));
}
Real MaterialParameters::shear_modulus() const { return young_modulus / (2 * (1 + poisson_ratio)); }
Real MaterialParameters::p_wave_modulus() const { return lame_lambda() + 2 * shear_modulus(); }

J2Parameters j2_parameters(const MaterialParameters& m) {
  return {m.young_modulus, m.poisson_ratio, m.initial_yield, m.saturation_yield, m.saturation_rate, m.linear_hardening};
}

void validate(const MaterialParameters& m, const std::string& where, const std::string& field) {
  if (!(m.young_modulus > 0) || !std::isfinite(m.young_modulus))
    throw InputError(where, field + ".young_modulus", "must be a positive pressure, e.g. 10MPa");
  if (!(m.poisson_ratio > -1 && m.poisson_ratio < 0.5))
    throw InputError(where, field + ".poisson_ratio", "must lie in (-1, 0.5)");
  if (!(m.density > 0) || !std::isfinite(m.density))
    throw InputError(where, field + ".density", "must be a positive density, e.g. 1050kg/m^3");
  if (m.kind == MaterialKind::j2) j2_parameters(m).validate(where + ": " + field);
}

}  // namespace latmpm::mpm
