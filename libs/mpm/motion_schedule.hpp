// A prescribed motion given as a schedule: the velocity of a rigid body against time, linear
// between knots (t_k, V_k) and held at the last V after the last knot. It is what a load–unload
// test needs (a platen driven down, stopped, driven back up): the constant velocity of a
// `driven` body cannot unload. The body follows the schedule exactly in position: its
// displacement is the integral of the piecewise-linear velocity, evaluated in closed form
// (a trapezoid per whole segment and the part of the segment the time lies in), so no
// error accumulates over the steps, whatever their size and wherever the knots fall.
#pragma once
#include <string>
#include <vector>

#include "mpm/real.hpp"

namespace latmpm::mpm {

struct VelocityKnot {
  Real time = 0;                  // s
  Vec3 velocity = Vec3::Zero();   // m/s
};

struct MotionSchedule {
  std::vector<VelocityKnot> knots;  // the first at t = 0, times strictly increasing

  bool empty() const { return knots.empty(); }
  // V(t) (m/s): linear between knots, the last knot's after it (t ≥ 0).
  Vec3 velocity(Real t) const;
  // D(t) = ∫_0^t V dt (m), exact for the piecewise-linear V.
  Vec3 displacement(Real t) const;
  // The largest speed |V| anywhere in the schedule (m/s): at a knot, since V is linear between.
  Real max_speed() const;
  // The direction of the first non-zero velocity (the loading axis); zero if every V is zero.
  Vec3 first_direction() const;
};

// Throws InputError(where, field, ...) for no knot, a first knot not at t = 0, times that do
// not increase strictly, or a non-finite value; `field` names the schedule's key
// (e.g. "rigid_bodies.platen.schedule").
void validate(const MotionSchedule& schedule, const std::string& where, const std::string& field);

}  // namespace latmpm::mpm
