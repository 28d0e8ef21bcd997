// A scene as a static problem (libs/statics): the deformable bodies' points are the
// material; the fixed bodies' points, held points and fixed rigid bodies are supports; the
// driven body (points, or a rigid box / half-space: the band nodes inside it) is the platen,
// moved along its velocity to run.end.plate_displacement.
#pragma once
#include <memory>
#include <vector>

#include "points/point_set.hpp"
#include "scene/scene.hpp"
#include "statics/displacement_control.hpp"

namespace latmpm {

struct StaticSceneProblem {
  std::unique_ptr<statics::StaticProblem> problem;
  statics::PlatenLoading loading;
  std::vector<size_t> material_points;  // PointSet index of each problem point
  std::vector<Eigen::Vector3d> half_size;  // of every PointSet point, m
  double contact_gap = 0;  // m: how far a rigid half-space was moved to touch the material
};

// Throws InputError (scene location) for what the static solver cannot run: free rigid
// bodies, DDMP, no or several driven bodies, no support.
StaticSceneProblem make_static_problem(const Scene& scene, const PointSet& points);

}  // namespace latmpm
