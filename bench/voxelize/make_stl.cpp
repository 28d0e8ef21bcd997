// Writes the closed test solids the voxelizer's data files and benchmarks use, in mm:
//   make_stl sphere RADIUS SUBDIVISIONS OUT.stl [ascii]   icosphere, 20·4^s triangles
//   make_stl cylinder RADIUS HEIGHT SEGMENTS OUT.stl [ascii]
//   make_stl box-with-hole EDGE OUT.stl                   a cube with one triangle missing
#include <cstdlib>
#include <iostream>
#include <string>

#include "mesh/primitive_meshes.hpp"
#include "mesh/stl_file.hpp"

int main(int argc, char** argv) {
  using namespace latmpm;
  const std::string kind = argc > 1 ? argv[1] : "";
  auto encoding = [&](int i) {
    return argc > i && std::string(argv[i]) == "ascii" ? StlEncoding::ascii : StlEncoding::binary;
  };
  const double mm = 1e-3;
  if (kind == "sphere" && argc >= 5) {
    write_stl(sphere_mesh({0, 0, 0}, std::atof(argv[2]) * mm, std::atoi(argv[3])), argv[4], mm, encoding(5));
  } else if (kind == "cylinder" && argc >= 6) {
    write_stl(cylinder_mesh({0, 0, 0}, std::atof(argv[2]) * mm, std::atof(argv[3]) * mm, std::atoi(argv[4])),
              argv[5], mm, encoding(6));
  } else if (kind == "box-with-hole" && argc >= 4) {
    const double a = std::atof(argv[2]) * mm;
    TriangleMesh box = box_mesh({0, 0, 0}, {a, a, a});
    box.triangles.erase(box.triangles.begin() + 2);  // one triangle of the top face
    write_stl(box, argv[3], mm);
  } else {
    std::cerr << "usage: make_stl sphere R S OUT [ascii] | cylinder R H N OUT [ascii] | box-with-hole A OUT\n";
    return 1;
  }
  return 0;
}
