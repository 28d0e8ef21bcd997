// Material parameters of a body, as a scene gives them. The constitutive models themselves
// live in linear_elastic.hpp, neo_hookean.hpp and j2_material.hpp.
#pragma once
#include <string>
#include <vector>

#include "mpm/real.hpp"

namespace latmpm::mpm {

enum class MaterialKind {
  linear_elastic,  // small-strain increments, Jaumann (objective) stress rate — paper A's model
  neo_hookean,     // compressible neo-Hookean, Bonet & Wood Eq. (5.29): σ = [μ(b−I) + λ ln J I]/J
  j2,              // finite-strain J2 plasticity of paper B (Eq. 9–13), j2_material.hpp
};

struct MaterialParameters {
  MaterialKind kind = MaterialKind::linear_elastic;
  Real young_modulus = 0;  // E, Pa
  Real poisson_ratio = 0;  // ν, dimensionless, in (-1, 0.5)
  Real density = 0;        // ρ0, kg/m³ (before the scene's mass scaling)
  // j2 only: the hardening law y(α) = y∞ + (y0 − y∞) e^(−η α) + h α (paper B Eq. 10).
  Real initial_yield = 0;     // y0, Pa
  Real saturation_yield = 0;  // y∞, Pa
  Real saturation_rate = 0;   // η, dimensionless
  Real linear_hardening = 0;  // h, Pa

  Real lame_lambda() const;  // λ = Eν / ((1+ν)(1−2ν)), Pa
  Real shear_modulus() const;  // μ = E / (2(1+ν)), Pa
  // P-wave modulus λ + 2μ (Pa): sets the dilatational wave speed sqrt((λ+2μ)/ρ).
  Real p_wave_modulus() const;
};

// "linear_elastic", "neo_hookean", "j2".
std::string to_string(MaterialKind kind);
std::vector<std::string> material_kind_names();  // names.cpp
MaterialKind parse_material_kind(const std::string& name, const std::string& where = "",
                                 const std::string& field = "");

struct J2Parameters;
// The J2 parameters of a j2 material (E, ν and the hardening law).
J2Parameters j2_parameters(const MaterialParameters& m);

// Throws InputError(where, field, ...) if E ≤ 0, ν outside (-1, 0.5) or ρ ≤ 0, or for j2 a
// hardening parameter is out of range (J2Parameters::validate).
void validate(const MaterialParameters& material, const std::string& where,
              const std::string& field);

}  // namespace latmpm::mpm
