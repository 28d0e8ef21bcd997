// Point placement on level sets of solids with exact volumes: lattice alignment, points per
// cell, volume accuracy and convergence, every point inside.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <tuple>

#include "shapes.hpp"
#include "voxelize/level_set_sampling.hpp"
#include "voxelize/voxelize.hpp"

using namespace latmpm;
using latmpm::test::analytic_solid;

namespace {

PointSet sample(const test::AnalyticSolid& solid, double cell, int ppc, bool curvature = true) {
  VoxelizeOptions o;
  o.cell_size = cell;
  o.ppc = ppc;
  const auto grid = solid.level_set(o.resolved_voxel_size(), o.band_half_width());
  SamplingOptions s;
  s.cell_size = cell;
  s.ppc = ppc;
  s.curvature_correction = curvature;
  return sample_level_set(*grid, s);
}

double total_volume(const PointSet& p) {
  double v = 0;
  for (double x : p.volume) v += x;
  return v;
}

}  // namespace

TEST_CASE("Analytic solids: total point volume within 0.5 % of the exact volume", "[voxelize]") {
  const std::string shape = GENERATE(as<std::string>{}, "sphere", "box", "capsule", "cylinder");
  const double points_per_radius = GENERATE(4.0, 6.0, 9.0);
  const int ppc = GENERATE(1, 2);
  const Eigen::Vector3d centre = GENERATE(Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(0.0123, -0.0071, 0.0311));
  const double r = 0.004;
  const double spacing = r / points_per_radius, cell = spacing * ppc;
  const auto solid = analytic_solid(shape, r, centre);
  const PointSet points = sample(solid, cell, ppc);
  const double error = total_volume(points) / solid.volume() - 1;
  INFO(shape << " at " << points_per_radius << " points per radius, ppc " << ppc << ": "
             << points.size() << " points, volume error " << error * 100 << " %");
  CHECK(std::fabs(error) < 0.005);
  double worst = -1;
  for (const auto& x : points.position) worst = std::max(worst, solid.distance(x));
  INFO("largest signed distance of a point " << worst / spacing << " spacings");
  CHECK(worst <= 0.01 * spacing);  // inside, up to the level set's own discretisation error
}
