// The gate an imported mesh passes before it is voxelized: check it (CGAL), optionally
// repair it, and refuse it if it is still not a closed solid — never voxelize a leaky mesh
// silently (meshToLevelSet misclassifies the inside of an open mesh).
#pragma once
#include <string>

#include "mesh/mesh_checks.hpp"
#include "mesh/mesh_repair.hpp"

namespace latmpm {

struct MeshGateResult {
  MeshReport found;      // before any repair
  bool repaired = false;
  RepairReport repair;   // what --repair did (when repaired)
  MeshReport result;     // the mesh that goes on (== found without repair)
};

// Throws InputError(where, "mesh", ...) when the (repaired) mesh does not enclose a volume,
// naming what is wrong and suggesting --repair when it was not tried. Self-intersections,
// degenerate and duplicate faces are reported but tolerated (meshToLevelSet copes).
MeshGateResult pass_mesh_gate(TriangleMesh& mesh, const std::string& where, bool repair,
                              bool find_self_intersections = true);

}  // namespace latmpm
