// Material points from a level set: ppc³ points per grid cell on the solver-aligned lattice
// x = (m + ½)·Δ, Δ = h/ppc (point_set.hpp), each with GIMP half-size Δ/2.
// Volumes: every lattice point gets Δ³ times the inside fraction of its sub-cell
// (sub_cell_fraction.hpp). Points whose centre lies inside the solid are kept; a point whose
// centre is outside but whose sub-cell reaches into the solid hands its share to an inside
// neighbour (the face neighbour along the surface normal for a flat surface). So every point
// lies inside the solid, surface points carry between ~½ and ~1½ Δ³, and the total volume is
// that of the fractions summed over the lattice.
#pragma once
#include <openvdb/openvdb.h>

#include <functional>
#include <string>
#include <vector>

#include "points/point_set.hpp"

namespace latmpm {

struct SamplingOptions {
  double cell_size = 0;  // h (m), > 0
  int ppc = 2;           // points per cell per direction, ≥ 1
  bool curvature_correction = true;  // see sub_cell_fraction.hpp; off only to measure it
};

// `level_set`: narrow-band signed distance in grid units (mm, levelset/level_set_units.hpp),
// negative inside, with the
// interior resolved (inactive values inside are −background), a uniform voxel no coarser than
// Δ/2 recommended, band half-width ≥ Δ/2 + √3 voxels. The level set's transform must be a pure
// uniform scale. Returns positions, volumes, half sizes; body ids all 0 and `body_names`
// empty (callers assign bodies). Points come in lattice order (z slowest, then y, then x).
// `progress(fraction_done)` is called from the calling thread now and then.
// Throws InputError("voxelize", ...) on invalid options or an unsuitable transform.
struct SamplingStats {
  // Volume (m³) of outside sub-cell shares with no inside neighbour to take them: features
  // thinner than about one point spacing. Lost from the total.
  double dropped_volume = 0;
};

PointSet sample_level_set(const openvdb::FloatGrid& level_set, const SamplingOptions& options,
                          const std::function<void(double)>& progress = {},
                          SamplingStats* stats = nullptr);

}  // namespace latmpm
