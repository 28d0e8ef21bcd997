// The quadrature-level graph of paper C Sec. 3.4: vertices are the quadrature points whose
// density exceeds a threshold, edges join lattice neighbours at Manhattan distance one.
//   narrow_band_mask: the narrow-band filter of Eq. (36): only the connected component with
//     the most points is simulated (plus points that must stay, e.g. loaded ones);
//   correct_connectivity: the correction after the optimisation (QR patterns, Fig. 7): for
//     two solid points in one cell or in two cells sharing a node whose graph distance
//     exceeds their Manhattan distance by more than `slack`, the points of one shortest
//     Manhattan path between them are made solid.
#pragma once
#include <vector>

#include "optimize/design_grid.hpp"

namespace latmpm::optimize {

// 1 for the points of the largest component of {ρ_q > threshold}, and for `keep` points.
// With `anchors` (points next to a support), the largest component holding an anchor and a
// kept point is taken, else the largest holding an anchor, else the largest: a larger
// free-floating piece would make the static solve singular.
// `joined` (optional) tells whether the chosen component holds an anchor and a kept point.
std::vector<char> narrow_band_mask(const DesignGrid& grid, const std::vector<Real>& density, Real threshold,
                                   const std::vector<size_t>& keep = {}, const std::vector<size_t>& anchors = {},
                                   bool* joined = nullptr);

// Number of connected components of {ρ_q > threshold}.
size_t component_count(const DesignGrid& grid, const std::vector<Real>& density, Real threshold);

// Sets to `solid` the points of the paths it creates; returns how many paths it created.
size_t correct_connectivity(const DesignGrid& grid, std::vector<Real>& density, Real threshold, int slack,
                            Real solid = 1);

}  // namespace latmpm::optimize
