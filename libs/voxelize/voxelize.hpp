// Geometry → material points: the voxelizer's two entry points. A strut graph goes straight
// to a level set of capsule distances (levelset/strut_level_set.hpp, no mesh in between), a
// closed mesh through OpenVDB's meshToLevelSet; both are then sampled on the solver-aligned
// point lattice (level_set_sampling.hpp). Validating inputs (mesh checks, resolution guard)
// is the caller's job: these functions trust their input.
#pragma once
#include <functional>
#include <string>

#include "geometry/strut_graph.hpp"
#include "mesh/triangle_mesh.hpp"
#include "points/point_set.hpp"
#include "voxelize/thin_features.hpp"

namespace latmpm {

struct VoxelizeOptions {
  double cell_size = 0;      // h (m), > 0
  int ppc = 2;               // points per cell per direction, ≥ 1
  double voxel_size = 0;     // level-set voxel (m); 0 = automatic, Δ/2 with Δ = h/ppc
  bool curvature_correction = true;
  // Strut graphs: tag the struts' points by strut group in at most this many colours for
  // grid contact (strut_partition.hpp); 0: no group tags.
  int strut_groups = 0;
  // Called with a stage name ("level set", "points") and the fraction of it done.
  std::function<void(const std::string&, double)> progress;

  double spacing() const { return cell_size / ppc; }
  double resolved_voxel_size() const { return voxel_size > 0 ? voxel_size : 0.5 * spacing(); }
  // Narrow-band half-width (voxels) the sampling needs: Δ/2 + √3 voxels, at least OpenVDB's 3.
  double band_half_width() const;
  // Inside a mesh the band reaches one cell and 2.5 voxels deep, so that walls and struts
  // thinner than two cells show as ridges of φ (thin_features.hpp).
  double interior_band_half_width() const;
};

struct Voxelized {
  PointSet points;
  double solid_volume = 0;  // m³: exact for a mesh, OpenVDB's level-set volume for a strut graph
  double voxel_size = 0;    // m
  size_t active_voxels = 0;
  double dropped_volume = 0;  // m³ of features thinner than a point spacing (level_set_sampling.hpp)
  ThinFeatures thin;          // meshes: walls and struts thinner than two cells
  double level_set_seconds = 0, sampling_seconds = 0;
};

// Bodies: the graph's strut body and one per plate (plates win where they overlap struts);
// tags "record", "bottom_layer", "top_layer" and one per plate (point_regions.hpp); the
// graph's parameters are copied; with options.strut_groups, the strut groups' tags
// "strut_c<k>" (strut_partition.hpp).
Voxelized voxelize_strut_graph(const StrutGraph& graph, const VoxelizeOptions& options);

// One body named `body_name`; tags "record", "bottom_layer", "top_layer".
// The mesh must enclose a volume (check_mesh(mesh).encloses_volume()).
Voxelized voxelize_mesh(const TriangleMesh& mesh, const std::string& body_name,
                        const VoxelizeOptions& options);

}  // namespace latmpm
