// The optimised part for the rest of the chain (issue 19): the binary design as
//   - a point-set file (docs/formats.md) of its solid quadrature points, on the lattice the
//     voxelizer uses (x = (i + (k + ½)/n)·h, volume s³ each, body "part"), so latmpm-solve
//     runs it on the same grid; a planar design is extruded through its thickness;
//   - mirrored through the scene's symmetry planes (load_case.hpp), so that a half model
//     exports the whole part;
//   - a closed triangle surface: a signed field over the solid voxels (size s) whose zero
//     iso-surface, meshed by OpenVDB's volumeToMesh (libs/levelset), lies on the faces between
//     solid and void voxels, written as STL in millimetres.
#pragma once
#include <string>
#include <vector>

#include "core/provenance.hpp"
#include "optimize/design_grid.hpp"
#include "optimize/load_case.hpp"

namespace latmpm::optimize {

struct ExportReport {
  size_t points = 0;
  size_t triangles = 0;
  Real surface_volume = 0;    // m³ enclosed by the surface (divergence theorem)
  bool closed = false;        // closed, consistently oriented outward
  Real solid_volume = 0;      // m³ of the solid points
};

// Writes `points_path` (HDF5) and `stl_path` (binary STL, mm); either may be empty (skipped).
ExportReport export_design(const DesignGrid& grid, const std::vector<Real>& binary,
                           const std::vector<SymmetryPlane>& mirror, const std::string& points_path,
                           const std::string& stl_path, const Provenance& provenance);

}  // namespace latmpm::optimize
