// Bodies: the point set's groups of points (by body name) and the role each plays. Bodies
// are data; the solver applies their boundary conditions in the grid update.
#pragma once
#include <string>

#include "mpm/material.hpp"
#include "mpm/real.hpp"

namespace latmpm::mpm {

enum class BodyRole {
  deformable,  // ordinary material: stress from its constitutive model
  fixed,       // rigid and at rest: every grid node its points touch gets zero velocity
  driven,      // rigid, moving at a prescribed velocity: its nodes get that velocity (the
               // paper's heavy-particle compressing plate, Paper A Sec. 4 and 5.1)
};

std::string to_string(BodyRole role);
BodyRole parse_body_role(const std::string& name, const std::string& where = "",
                         const std::string& field = "");

struct BodySettings {
  std::string name;  // must match a name in PointSet::body_names
  BodyRole role = BodyRole::deformable;
  // Constitutive model and density. Used for deformable bodies; rigid bodies (fixed,
  // driven) only use `density` for their reported mass.
  MaterialParameters material;
  Vec3 velocity = Vec3::Zero();  // m/s, the prescribed velocity of a driven body
};

}  // namespace latmpm::mpm
