// Hexahedral meshes through gmsh (libs/hexmesh): pure trilinear hexahedra, exact volumes
// (box; the cylinder's inscribed prism, converging to πr²h), .msh round trip with units,
// refusal of other element types, and the point set with its CPDI1 vertices.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "hexmesh/hex_mesh.hpp"
#include "hexmesh/hex_points.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

struct Scratch : test::ScratchDir {
  explicit Scratch(const std::string& name) : test::ScratchDir("hexmesh-" + name), dir(path()) {}
  fs::path dir;
};

// Volume of the prism over the regular N-gon inscribed in the circle of radius r.
double inscribed_prism(double r, double height, int sides) {
  return height * sides / 2.0 * r * r * std::sin(2 * M_PI / sides);
}

}  // namespace

TEST_CASE("A structured box mesh has the box's exact volume in n_x n_y n_z hexahedra", "[hexmesh]") {
  const HexMesh mesh = box_hex_mesh({0.1, -0.2, 0.3}, {1.1, 0.4, 0.8}, {5, 3, 4});
  CHECK(mesh.elements.size() == 60);
  CHECK(mesh.nodes.size() == 6 * 4 * 5);
  CHECK(hex_mesh_volume(mesh) == Approx(1.0 * 0.6 * 0.5).epsilon(1e-13));
}

TEST_CASE("The O-grid cylinder is all hexahedra with the inscribed prism's volume, converging to pi r^2 h",
          "[hexmesh]") {
  const double d = 4e-3, h = 4e-3, r = d / 2;
  double previous_error = INFINITY;
  for (int level = 1; level <= 3; ++level) {
    const CylinderMeshSpec spec = paper_b_cylinder(level, d, h);
    const HexMesh mesh = cylinder_hex_mesh(spec);
    CHECK(mesh.elements.size() == size_t(48 * level * level * level));
    CHECK(int(mesh.elements.size()) == spec.elements());
    const double volume = hex_mesh_volume(mesh);
    CHECK(volume == Approx(inscribed_prism(r, h, 4 * spec.core_divisions)).epsilon(1e-12));
    const double error = std::abs(volume / (M_PI * r * r * h) - 1);
    // Second order in the element size: 1 − sin(2π/N)/(2π/N) ≈ (2π/N)²/6 for N = 4·core.
    const double sides = 4 * spec.core_divisions;
    if (level > 1) CHECK(error / previous_error == Approx(std::pow((sides - 8) / sides, 2)).epsilon(0.05));
    previous_error = error;
    double r_max = 0, z_min = INFINITY, z_max = -INFINITY;
    for (const auto& x : mesh.nodes) {
      r_max = std::max(r_max, std::hypot(x.x(), x.y()));
      z_min = std::min(z_min, x.z()), z_max = std::max(z_max, x.z());
    }
    CHECK(r_max == Approx(r).epsilon(1e-12));
    CHECK(z_min == Approx(0).margin(1e-15));
    CHECK(z_max == Approx(h).epsilon(1e-12));
  }
}

TEST_CASE("A written .msh reads back with its unit, and CPDI points carry exact volumes and vertices",
          "[hexmesh]") {
  Scratch scratch("roundtrip");
  CylinderMeshSpec spec = paper_b_cylinder(1, 4, 4);  // written in millimetres
  spec.core_divisions = 3;
  const HexMesh made = cylinder_hex_mesh(spec, scratch / "c.msh");
  const HexMesh read = read_hex_mesh(scratch / "c.msh", 1e-3);
  REQUIRE(read.elements.size() == made.elements.size());
  CHECK(hex_mesh_volume(read) == Approx(1e-9 * hex_mesh_volume(made)).epsilon(1e-12));
  const PointSet points = hex_mesh_points(read, "specimen", 0.4e-3);
  REQUIRE_NOTHROW(points.validate("test"));
  double total = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    total += points.volume[i];
    const HexIntegrals hex = hex_integrals(points.domain_vertices[i]);
    CHECK((hex.centroid - points.position[i]).norm() <= 1e-15);
    CHECK(hex.min_jacobian > 0);
  }
  CHECK(total == Approx(inscribed_prism(2e-3, 4e-3, 12)).epsilon(1e-12));
  {
    Hdf5File f(scratch / "p.h5", Hdf5File::Mode::create);
    write_point_set(f, points);
  }
  const PointSet back = read_point_set(Hdf5File(scratch / "p.h5", Hdf5File::Mode::read));
  REQUIRE(back.domain_vertices.size() == points.size());
  for (size_t i = 0; i < points.size(); ++i)
    for (int a = 0; a < 8; ++a) CHECK(back.domain_vertices[i][size_t(a)] == points.domain_vertices[i][size_t(a)]);
}

TEST_CASE("Point sets without vertices still read (the format change is backward compatible)", "[hexmesh]") {
  Scratch scratch("compatible");
  PointSet p = hex_mesh_points(box_hex_mesh({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), "block", 0.5);
  p.domain_vertices.clear();
  {
    Hdf5File f(scratch / "p.h5", Hdf5File::Mode::create);
    write_point_set(f, p);
  }
  const Hdf5File f(scratch / "p.h5", Hdf5File::Mode::read);
  CHECK_FALSE(f.exists("/points/domain_vertices"));
  const PointSet back = read_point_set(f);
  CHECK(back.size() == 8);
  CHECK(back.domain_vertices.empty());
}

TEST_CASE("Meshes of tetrahedra, missing files and inverted elements are refused naming the file", "[hexmesh]") {
  Scratch scratch("refuse");
  std::ofstream(scratch / "tet.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
                                        "4 0 0 1\n$EndNodes\n$Elements\n1\n1 4 2 0 1 1 2 3 4\n$EndElements\n";
  CHECK_THROWS_WITH(read_hex_mesh(scratch / "tet.msh", 1), Catch::Contains("tet.msh") && Catch::Contains("tetrahedra"));
  CHECK_THROWS_AS(read_hex_mesh(scratch / "missing.msh", 1), InputError);
  // One hexahedron with two vertices swapped across the element: det J changes sign inside.
  std::ofstream(scratch / "bad.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n"
                                        "4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n$EndNodes\n$Elements\n1\n"
                                        "1 5 2 0 1 7 2 3 4 5 6 1 8\n$EndElements\n";
  CHECK_THROWS_WITH(read_hex_mesh(scratch / "bad.msh", 1), Catch::Contains("bad.msh") && Catch::Contains("inverted"));
  // The same element in mirrored order (all Jacobians negative) is accepted and turned.
  std::ofstream(scratch / "mirrored.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n"
                                             "4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n$EndNodes\n$Elements\n1\n"
                                             "1 5 2 0 1 5 6 7 8 1 2 3 4\n$EndElements\n";
  CHECK(hex_mesh_volume(read_hex_mesh(scratch / "mirrored.msh", 2)) == Approx(8).epsilon(1e-14));
}
