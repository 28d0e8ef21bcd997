// The gate an imported mesh passes before it is voxelized: weld near-coincident vertices
// (vertex_weld.hpp), check it (CGAL), optionally repair it, and refuse it if it is still not
// a closed solid — never voxelize a leaky mesh
// silently (meshToLevelSet misclassifies the inside of an open mesh).
#pragma once
#include <string>

#include "mesh/mesh_checks.hpp"
#include "mesh/mesh_repair.hpp"
#include "mesh/vertex_weld.hpp"

namespace latmpm {

struct MeshGateResult {
  WeldReport weld;       // near-coincident vertices merged before the checks
  MeshReport found;      // before any repair
  bool repaired = false;
  RepairReport repair;   // what --repair did (when repaired)
  MeshReport result;     // the mesh that goes on (== found without repair)
};

// Throws InputError(where, "mesh", ...) when the (repaired) mesh does not enclose a volume,
// naming what is wrong and suggesting --repair when it was not tried, and when --repair had
// to fill holes making more than max_filled_area_fraction of the surface (an open sheet, a
// triangle soup: what hole filling closes is not the part). Self-intersections,
// degenerate and duplicate faces are reported but tolerated (meshToLevelSet copes).
MeshGateResult pass_mesh_gate(TriangleMesh& mesh, const std::string& where, bool repair,
                              bool find_self_intersections = true);

}  // namespace latmpm
