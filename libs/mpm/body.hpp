// Bodies: the point set's groups of points (by body name) and the role each plays. Bodies
// are data; the solver applies their boundary conditions in the grid update.
#pragma once
#include <string>
#include <vector>

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
std::vector<std::string> body_role_names();  // names.cpp
BodyRole parse_body_role(const std::string& name, const std::string& where = "",
                         const std::string& field = "");

struct BodySettings {
  std::string name;  // must match a name in PointSet::body_names
  BodyRole role = BodyRole::deformable;
  // Constitutive model and density. Used for deformable bodies; rigid bodies (fixed,
  // driven) only use `density` for their reported mass.
  MaterialParameters material;
  Vec3 velocity = Vec3::Zero();  // m/s, the prescribed velocity of a driven body
  // Deformable bodies only: the body's points carrying this point-set tag are held (Paper A
  // Sec. 5.1, "fixed at the bottom"): every grid node their stencils reach gets zero
  // velocity, like a fixed body's nodes, and the force that takes is this body's reaction.
  // The held points stay deformable, so a record layer among them still measures stress.
  // Empty: nothing held.
  std::string hold_tag;
  // false: the held nodes are clamped (zero velocity, the paper's "fixed"). true: they only
  // lose the velocity component normal to the held face (a roller support), so the held
  // face may expand sideways and the record layer at it is not stiffened by the clamp.
  bool hold_slip = false;
};

}  // namespace latmpm::mpm
