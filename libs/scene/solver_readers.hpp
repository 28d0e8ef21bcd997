// The solver's parameter structs read from the scene's tables: one read() per struct, so a
// new solver setting is its field (with its default) in the struct and its line here.
// Each value is checked as it is read; an error names the file and line, the key path and
// what is wrong (toml_table_reader.hpp). Defaults are the structs' own, or for the choices
// that depend on the shape function, mpm's (default_cfl, default_scheme in mpm/names.cpp).
//
// Private to libs/scene (toml++ behind TableReader).
#pragma once
#include "mpm/material.hpp"
#include "mpm/rigid_body.hpp"
#include "mpm/settings.hpp"
#include "scene/toml_table_reader.hpp"
#include "statics/static_settings.hpp"

namespace latmpm::scene_toml {

// mpm::Settings from [grid] (cell, shape, scheme, flip, ddmp_*), [time] (dt or cfl,
// mass_scaling unless the quasi-static mode picks it), [gravity] (g) and output.record_tag.
// The caller finishes the tables, which also hold keys of the scene's own.
void read(TableReader& grid, TableReader& time, TableReader& gravity, TableReader& output,
          mpm::Settings& settings);

// [bodies.<name>.material]: model, E, nu, density, and for j2 the hardening law.
void read(TableReader& material, mpm::MaterialParameters& parameters);

// [rigid_bodies.<name>]: motion, shape and its geometry, velocity, mass, gravity, contact.
// The name is the caller's; plane_normal is made a unit vector.
void read(TableReader& body, mpm::RigidBodySettings& settings);

// [solver] of a static run: increments, linear_solver, tolerance, check_stability,
// predictor, stabilisation.
void read(TableReader& solver, statics::StaticSettings& settings);

}  // namespace latmpm::scene_toml
