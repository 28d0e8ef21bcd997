#include "hexmesh/hex_points.hpp"

#include "points/hexahedron.hpp"

namespace latmpm {

PointSet hex_mesh_points(const HexMesh& mesh, const std::string& body_name, double cell_size) {
  PointSet p;
  p.body_names = {body_name};
  p.cell_size = cell_size;
  p.ppc = 1;
  p.parameters["domains"] = "hexahedra";
  p.parameters["elements"] = std::to_string(mesh.elements.size());
  for (const auto& element : mesh.elements) {
    HexVertices x;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
    for (int a = 0; a < 8; ++a) {
      x[size_t(a)] = mesh.nodes[element[size_t(a)]];
      lo = lo.cwiseMin(x[size_t(a)]);
      hi = hi.cwiseMax(x[size_t(a)]);
    }
    const HexIntegrals integrals = hex_integrals(x);
    p.position.push_back(integrals.centroid);
    p.volume.push_back(integrals.volume);
    p.body.push_back(0);
    p.half_size.push_back((hi - lo) / 2);
    p.domain_vertices.push_back(x);
  }
  return p;
}

}  // namespace latmpm
