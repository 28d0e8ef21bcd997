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

TEST_CASE("Points sit on the solver-aligned lattice with ppc³ full points per interior cell", "[voxelize]") {
  const int ppc = GENERATE(1, 2, 3);
  const double h = 0.001, spacing = h / ppc;
  // A block whose faces fall between lattice planes, so it has cut surface cells.
  const auto block = analytic_solid("box", 0.0047, Eigen::Vector3d(0.0003, -0.0011, 0.0071));
  const PointSet points = sample(block, h, ppc);
  REQUIRE(points.size() > 0);
  CHECK(points.cell_size == h);
  CHECK(points.ppc == ppc);
  std::map<std::tuple<long, long, long>, int> per_cell;
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& x = points.position[i];
    for (int a = 0; a < 3; ++a) {
      const double m = x[a] / spacing - 0.5;  // (m + ½)Δ: m must be an integer
      CHECK(std::fabs(m - std::round(m)) < 1e-9);
    }
    CHECK(points.half_size[i].isApprox(Eigen::Vector3d::Constant(spacing / 2)));
    ++per_cell[{std::lround(std::floor(x.x() / h)), std::lround(std::floor(x.y() / h)),
                std::lround(std::floor(x.z() / h))}];
  }
  // Cells entirely inside the block hold ppc³ points of volume Δ³ each.
  size_t interior_cells = 0;
  for (const auto& [cell, count] : per_cell) {
    const Eigen::Vector3d lo(std::get<0>(cell) * h, std::get<1>(cell) * h, std::get<2>(cell) * h);
    const Eigen::Vector3d hi = lo + Eigen::Vector3d::Constant(h);
    if (block.distance(lo) > -spacing || block.distance(hi) > -spacing) continue;
    if ((block.a.array() > lo.array() - spacing).any() || (block.b.array() < hi.array() + spacing).any()) continue;
    ++interior_cells;
    CHECK(count == ppc * ppc * ppc);
  }
  CHECK(interior_cells > 0);
  for (size_t i = 0; i < points.size(); ++i)
    if (block.distance(points.position[i]) < -1.5 * spacing)
      CHECK(points.volume[i] == Approx(spacing * spacing * spacing).epsilon(1e-12));
}

TEST_CASE("The total volume converges as the cell shrinks", "[voxelize]") {
  // Root-mean-square error over placements of a sphere, as the spacing halves.
  const double r = 0.003;
  std::vector<double> rms;
  const std::vector<double> resolutions = {3.0, 6.0, 12.0, 24.0};
  for (double points_per_radius : resolutions) {
    double sum = 0;
    const int placements = 8;
    for (int k = 0; k < placements; ++k) {
      const double s = r / points_per_radius;
      const Eigen::Vector3d c = s * Eigen::Vector3d(std::fmod(0.37 * k, 1.0), std::fmod(0.61 * k, 1.0), std::fmod(0.83 * k, 1.0));
      const auto sphere = analytic_solid("sphere", r, c);
      const double e = total_volume(sample(sphere, s, 1)) / sphere.volume() - 1;
      sum += e * e;
    }
    rms.push_back(std::sqrt(sum / placements));
  }
  std::string table;
  for (size_t i = 0; i < rms.size(); ++i)
    table += std::to_string(resolutions[i]) + " points per radius: rms error " + std::to_string(rms[i]) + "\n";
  INFO(table);
  CHECK(rms[2] < rms[0]);
  CHECK(rms[3] < rms[1]);
  CHECK(rms[3] < 0.001);
}

TEST_CASE("Without the curvature term a sphere is over-counted by Δ²/(4R²)", "[voxelize]") {
  // sub_cell_fraction.hpp: the planar rule's excess on a sphere of radius R is Δ²/(4R²);
  // the difference between the uncorrected and corrected totals must be that.
  const double r = 0.004;
  const double points_per_radius = GENERATE(4.0, 8.0);
  const double spacing = r / points_per_radius;
  const auto sphere = analytic_solid("sphere", r, Eigen::Vector3d(0.00011, -0.00023, 0.00005));
  const double corrected = total_volume(sample(sphere, spacing, 1, true));
  const double planar = total_volume(sample(sphere, spacing, 1, false));
  const double predicted = spacing * spacing / (4 * r * r);
  INFO("measured excess " << (planar - corrected) / sphere.volume() << ", predicted " << predicted);
  CHECK((planar - corrected) / sphere.volume() == Approx(predicted).epsilon(0.15));
  CHECK(std::fabs(corrected / sphere.volume() - 1) < std::fabs(planar / sphere.volume() - 1));
}
