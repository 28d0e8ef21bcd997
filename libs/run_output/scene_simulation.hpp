// From a scene to the solver's input: settings and body settings for mpm::Simulation.
// The scene already holds the solver's own structs (scene.hpp); what is left here is what
// the command line adds (threads), the density a rigid point body borrows, validation, and
// the quantities the run derives from the scene (loading axis, end time).
#pragma once
#include <vector>

#include "mpm/body.hpp"
#include "mpm/rigid_body.hpp"
#include "mpm/settings.hpp"
#include "scene/scene.hpp"

namespace latmpm {

mpm::Settings solver_settings(const Scene& scene, int threads);
// One per scene body, in scene order. A fixed or driven body without a material takes the
// density of the first deformable body (its motion is prescribed; the density only sets
// the mass it reports).
std::vector<mpm::BodySettings> solver_bodies(const Scene& scene);
// The scene's [rigid_bodies], in scene order.
std::vector<mpm::RigidBodySettings> solver_rigid_bodies(const Scene& scene);

// The loading axis: the unit direction of the (first) driven body's velocity (point bodies
// first, then rigid ones); without a driven body, that of the first free rigid body's
// initial velocity (the flyer's approach); then the direction of gravity; without gravity, -z. Loads in the series are
// components along it, compression positive.
Eigen::Vector3d loading_axis(const Scene& scene);
// Simulated time at which the run ends (s): the end time, or the plate displacement
// divided by the driven body's speed (point or rigid).
double end_time(const Scene& scene);

}  // namespace latmpm
