// The optimised part's export (design_export.hpp): the STL is closed and outward and encloses
// the solid points' volume (within the bevel marching cubes cuts along the voxel edges), and
// the point-set file holds one point of volume s³ per solid voxel on the voxelizer's lattice.
#include <catch2/catch.hpp>

#include "core/hdf5_file.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/stl_file.hpp"
#include "optimize/design_export.hpp"
#include "points/point_set.hpp"
#include "scratch_dir.hpp"
#include "small_cantilever.hpp"

using namespace latmpm;
using namespace latmpm::optimize;

TEST_CASE("An exported design is a closed surface around its solid points and a point-set file", "[optimize]") {
  latmpm::test::ScratchDir scratch("optimize-export");
  const int variant = GENERATE(0, 1, 2);  // planar; 3D; 3D half model mirrored through z = 0
  const bool planar = variant == 0;
  std::vector<SymmetryPlane> mirror;
  if (variant == 2) mirror.push_back({2, false});
  const DesignGrid g = optimize::test::small_grid(planar);
  // An L: the bottom two point rows and the left two point columns.
  std::vector<double> binary(g.point_count(), 0);
  size_t solid = 0;
  for (size_t q = 0; q < g.point_count(); ++q) {
    const Index3 l = g.lattice_coord(q);
    if (l[1] < 2 || l[0] < 2) binary[q] = 1, ++solid;
  }
  const ExportReport r = export_design(g, binary, mirror, scratch / "part.h5", scratch / "part.stl",
                                       Provenance::for_run("test", 0, nullptr));
  const double s = g.spacing();
  const size_t layers = planar ? size_t(std::lround(g.thickness / s)) : variant == 2 ? 2 : 1;  // (images)
  CHECK(r.points == solid * layers);
  CHECK(r.solid_volume == Approx(double(solid * layers) * s * s * s));
  CHECK(r.closed);

  const TriangleMesh mesh = read_stl(scratch / "part.stl", 1e-3);
  const MeshReport checked = check_mesh(mesh, false);
  CHECK(checked.encloses_volume());
  CAPTURE(planar, checked.volume, r.solid_volume);
  CHECK(checked.volume == Approx(r.solid_volume).epsilon(0.05));

  const PointSet points = read_point_set(Hdf5File(scratch / "part.h5", Hdf5File::Mode::read));
  CHECK(points.size() == r.points);
  CHECK(points.cell_size == g.cell_size);
  CHECK(points.ppc == g.per_cell);
  for (size_t p = 0; p < points.size(); ++p) {
    CHECK(points.volume[p] == Approx(s * s * s));
    // On the lattice (i + ½) s.
    for (int a = 0; a < 3; ++a) CHECK(std::abs(std::fmod(std::abs(points.position[p][a]) / s, 1.0) - 0.5) < 1e-9);
  }
  if (variant == 2) {  // the image of every point through z = 0
    size_t below = 0;
    for (size_t p = 0; p < points.size(); ++p) below += points.position[p][2] < 0;
    CHECK(below == points.size() / 2);
    double z_min = 0;
    for (const auto& v : mesh.vertices) z_min = std::min(z_min, double(v[2]));
    CHECK(z_min == Approx(-g.extent()[2]));
  }
}

TEST_CASE("A support holding one component on a domain face is a symmetry plane", "[optimize]") {
  const DesignGrid g = optimize::test::small_grid(false);
  LoadCase c;
  const double h = g.cell_size;
  const Vec3 big = Vec3::Constant(100 * h);
  c.supports.push_back({{-big, Vec3(0, big[1], big[2])}, {true, true, true}, "clamp"});           // not one component
  c.supports.push_back({{-big, Vec3(big[0], big[1], 0)}, {false, false, true}, "z = 0"});       // a plane
  c.supports.push_back({{-big, Vec3(big[0], 2 * h, big[2])}, {false, true, false}, "y band"});   // reaches inside
  c.supports.push_back({{Vec3(g.extent()[0], -big[1], -big[2]), big}, {true, false, false}, "x far"});
  const std::vector<SymmetryPlane> planes = symmetry_planes(g, c);
  REQUIRE(planes.size() == 2);
  CHECK((planes[0].axis == 2 && !planes[0].far_face));
  CHECK((planes[1].axis == 0 && planes[1].far_face));
}
