// Does every driven body ever touch material? A part placed off the platen (an STL standing
// elsewhere than z = 0, a platen above the part's top) gives a run whose load stays zero, with
// no error: warn before stepping. Conservative: the driven body's box swept along its velocity
// over the run's travel, grown by one grid cell (where grid coupling reaches), must meet the
// sub-cell of a deformable point; an oblique sweep is boxed, so it can only miss a warning.
#pragma once
#include <string>
#include <vector>

#include "points/point_set.hpp"
#include "scene/scene.hpp"

namespace latmpm {

// One line per driven body (point body or rigid box or half-space) that never comes within a
// cell of a deformable point, naming it, its travel and the gap; empty when all do.
std::vector<std::string> driven_body_warnings(const Scene& scene, const PointSet& points);

}  // namespace latmpm
