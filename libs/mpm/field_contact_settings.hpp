// The settings of multi-field grid contact (field_contact.hpp): the scene's [contact] table.
#pragma once
#include <string>
#include <vector>

#include "mpm/real.hpp"
#include "mpm/shape_function_kind.hpp"

namespace latmpm::mpm {

enum class UpdateScheme;

struct FieldContactSettings {
  bool enabled = false;
  Real friction = 0;                // Coulomb coefficient μ ≥ 0 between fields
  std::vector<std::string> groups;  // point tags: each makes a field of its own in every body it tags;
                                    // "prefix*" stands for every tag of the point set starting with prefix
  std::vector<std::string> bonded_bodies;  // deformable bodies whose rest fields move as one where they meet
  // Fields in contact only where their points' reference volume on the node, Σ_k m_k/ρ_k,
  // fills at least this fraction of the node's h³ (Nairn 2013's volume check): without it
  // fields touch as soon as they share a node, up to 1.5 cells apart with GIMP.
  Real fill = 0.9;  // in (0, 1]; 0: no check
};

// Throws InputError for a negative or non-finite friction, or contact with a shape or
// scheme its step does not take (DDMP, CPDI1; USF, MUSL): field_contact_step.cpp.
void validate(const FieldContactSettings& contact, ShapeFunctionKind shape, UpdateScheme scheme,
              const std::string& where);

}  // namespace latmpm::mpm
