#include "voxelize/thin_features.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "levelset/level_set_units.hpp"

namespace latmpm {

namespace {

// Local thickness, as the largest inscribed ball through a point (Hildebrand & Rüegsegger
// 1997, J. Microsc. 185): the ridge also runs from a thick region out to its convex edges
// (the bisector of a corner, shallow near the edge), where the ball through the point is
// the thick region's. Such a ridge voxel has a voxel deeper than itself within its own
// depth (+2 voxels); the mid-surface of a thin wall or the axis of a thin strut has none.
// Inactive voxels inside lie beyond the interior band: deep.
bool deeper_nearby(const openvdb::FloatGrid::ConstAccessor& accessor, const openvdb::Coord& c, double phi_voxels,
                   double voxel) {
  const int r = static_cast<int>(std::ceil(-phi_voxels)) + 2;
  const double deeper = (phi_voxels - 0.75) * voxel;  // grid units
  for (int i = -r; i <= r; ++i)
    for (int j = -r; j <= r; ++j)
      for (int k = -r; k <= r; ++k) {
        float value;
        const bool active = accessor.probeValue(c.offsetBy(i, j, k), value);
        if ((!active && value < 0) || value < deeper) return true;
      }
  return false;
}

}  // namespace

ThinFeatures find_thin_features(const openvdb::FloatGrid& level_set, double limit) {
  ThinFeatures out;
  out.limit = limit;
  const double voxel = level_set.voxelSize()[0];  // grid units
  const double to_metres = 1.0 / grid_units_per_metre;
  auto accessor = level_set.getConstAccessor();
  std::vector<double> thin;
  for (auto it = level_set.cbeginValueOn(); it; ++it) {
    const double phi = *it / voxel;  // in voxels
    if (phi >= 0) continue;
    const openvdb::Coord c = it.getCoord();
    double apex = 0;  // the deepest V apex over the axes where this voxel is a ridge
    bool ridge = false;
    for (int a = 0; a < 3; ++a) {
      openvdb::Coord step(0, 0, 0);
      step[a] = 1;
      // Only active neighbours hold distances: past the band's inner edge the inactive value
      // (−background) would make a false ridge.
      float values[4];
      const openvdb::Coord at[4] = {c - step, c + step, c - step - step, c + step + step};
      bool active = true;
      for (int n = 0; n < 4; ++n) active = accessor.probeValue(at[n], values[n]) && active;
      if (!active) continue;
      const double back = values[0] / voxel, ahead = values[1] / voxel, back2 = values[2] / voxel, ahead2 = values[3] / voxel;
      if (!(phi <= back && phi <= ahead && back2 - phi >= 0.5 && ahead2 - phi >= 0.5)) continue;
      // V through (−1, back), (0, phi), (1, ahead): slope s, apex offset c ∈ [0, ½], depth m.
      const double rise_low = std::min(back, ahead) - phi, rise_high = std::max(back, ahead) - phi;
      if (!(rise_high > 0)) continue;
      const double offset = 0.5 * (rise_high - rise_low) / rise_high;
      const double m = phi - rise_high * offset;
      if (!ridge || m > apex) apex = m;  // the least deep: the thinnest direction through here
      ridge = true;
    }
    if (!ridge) continue;
    ++out.ridge_voxels;
    const double thickness = -2 * apex * voxel * to_metres;
    if (!(thickness < limit) || deeper_nearby(accessor, c, phi, voxel)) continue;
    thin.push_back(thickness);
  }
  out.thin_voxels = thin.size();
  if (!thin.empty()) {
    // The tenth percentile, not the minimum: single voxels off the mid-surface (within the
    // 0.75-voxel tolerance of deeper_nearby) read up to 1.5 voxels thin.
    const size_t k = thin.size() / 10;
    std::nth_element(thin.begin(), thin.begin() + long(k), thin.end());
    out.thinnest = thin[k];
  }
  return out;
}

std::string describe(const ThinFeatures& t, double cell_size) {
  if (!t.any()) return "";
  char text[320];
  std::snprintf(text, sizeof text,
                "thinnest wall or strut %.3g mm, %.2g cells across (two cells: %.3g mm, %.3g mm more); "
                "%.0f %% of the measured mid-surface is thinner than two cells",
                t.thinnest * 1e3, t.thinnest / cell_size, 2 * cell_size * 1e3, (2 * cell_size - t.thinnest) * 1e3,
                100.0 * double(t.thin_voxels) / double(std::max<size_t>(t.ridge_voxels, 1)));
  return text;
}

}  // namespace latmpm
