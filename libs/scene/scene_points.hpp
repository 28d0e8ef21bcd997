// The material points of a scene: every [[points]] file read and merged into one PointSet
// whose bodies are the scene's bodies in scene order (body index i = scene.bodies[i]).
// Checked both ways: a body in a point file that [bodies] does not describe is an error, and
// so is a described body that no file holds; both messages name the scene line.
#pragma once
#include "points/point_set.hpp"
#include "scene/scene.hpp"

namespace latmpm {

struct Provenance;

// Reads and validates the point files; when `provenance` is given, records each file as an
// input and inherits its history. Tags missing from a file are 0 for its points.
PointSet load_scene_points(const Scene& scene, Provenance* provenance = nullptr);

}  // namespace latmpm
