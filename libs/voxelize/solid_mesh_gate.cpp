#include "voxelize/solid_mesh_gate.hpp"

#include <sstream>

#include "core/errors.hpp"

namespace latmpm {

MeshGateResult pass_mesh_gate(TriangleMesh& mesh, const std::string& where, bool repair,
                              bool find_self_intersections) {
  MeshGateResult r;
  r.found = check_mesh(mesh, find_self_intersections);
  r.result = r.found;
  if (repair) {
    r.repair = repair_mesh(mesh);
    r.repaired = true;
    r.result = check_mesh(mesh, find_self_intersections);
  }
  const MeshReport& m = r.result;
  if (m.encloses_volume()) return r;
  std::ostringstream why;
  if (!m.closed()) {
    why << "not a closed solid (" << m.boundary_edges << " boundary edges, " << m.non_manifold_edges
        << " non-manifold edges)";
  } else if (!m.consistently_oriented) {
    why << "faces are not consistently oriented";
  } else {
    why << "encloses no volume";
  }
  why << (repair ? " even after --repair" : "; --repair may fix it");
  throw InputError(where, "mesh", why.str());
}

}  // namespace latmpm
