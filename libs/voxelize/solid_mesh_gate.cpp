#include "voxelize/solid_mesh_gate.hpp"

#include <sstream>

#include "core/errors.hpp"

namespace latmpm {

MeshGateResult pass_mesh_gate(TriangleMesh& mesh, const std::string& where, bool repair,
                              bool find_self_intersections) {
  MeshGateResult r;
  r.weld = weld_nearby_vertices(mesh);
  r.found = check_mesh(mesh, find_self_intersections);
  r.result = r.found;
  if (repair) {
    r.repair = repair_mesh(mesh);
    r.repaired = true;
    r.result = check_mesh(mesh, find_self_intersections);
  }
  const MeshReport& m = r.result;
  std::ostringstream why;
  const double filled = r.repaired && r.repair.surface_area > 0 ? r.repair.filled_area / r.repair.surface_area : 0;
  if (filled > max_filled_area_fraction) {
    why.precision(3);
    why << "not a solid even after --repair: hole filling had to invent " << 100 * filled
        << " % of the surface (at most " << 100 * max_filled_area_fraction
        << " %): an open sheet or a triangle soup, not a part with a few faces missing";
    throw InputError(where, "mesh", why.str());
  }
  if (m.encloses_volume()) return r;
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
