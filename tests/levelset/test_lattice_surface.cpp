// The STL that latmpm-lattice --stl writes: a valid closed solid (checked with CGAL through
// libs/mesh) that encloses the level-set volume. Small lattices keep the CGAL
// self-intersection search fast; the surface is the tool's (strut_graph_surface, STL in mm).
#include <catch2/catch.hpp>

#include <filesystem>

#include "geometry/column.hpp"
#include "geometry/lattice.hpp"
#include "levelset/level_set_mesh.hpp"
#include "levelset/strut_level_set.hpp"
#include "levelset/strut_surface.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/stl_file.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;

TEST_CASE("The STL of a lattice or column is a closed outward solid enclosing the level-set volume",
          "[levelset][stl]") {
  const std::string which = GENERATE("T1P20", "T2P40", "bcc", "column");
  CAPTURE(which);
  StrutGraph graph;
  double voxel = 0;
  if (which == "column") {
    graph = build_column({1.6e-3, 8e-3, 1e-3, 0.4e-3});
    voxel = 0.1e-3;
  } else {
    LatticeSpec spec;
    if (which == "bcc") {
      spec.cell = "bcc";
      spec.strut_length = 4e-3;
      spec.strut_diameter = 1e-3;
      spec.plate_thickness = 1e-3;
    } else {
      spec = preset_lattice(which);
    }
    spec.cells = {2, 1, 2};  // two layers: a layer joint and plate contacts, small enough for CGAL
    graph = build_lattice(spec);
    voxel = spec.strut_diameter / 16;  // 8 voxels per radius
  }
  const test::ScratchDir scratch("surface");
  const std::string path = scratch / (which + ".stl");
  write_stl(strut_graph_surface(graph, voxel), path, 1e-3);
  const TriangleMesh mesh = read_stl(path, 1e-3);
  std::filesystem::remove(path);

  const MeshReport report = check_mesh(mesh, true);
  INFO(describe(report));
  CHECK(report.closed());
  CHECK(report.consistently_oriented);
  CHECK(report.outward);
  CHECK(report.non_manifold_edges == 0);
  CHECK(report.self_intersecting_pairs == 0);
  CHECK(report.is_valid_solid());
  const double level_set = level_set_volume(*strut_graph_level_set(graph, voxel, 3.0));
  CHECK(report.volume == Approx(level_set).epsilon(0.02));
}
