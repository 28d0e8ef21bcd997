// The closed, outward triangle surface of a strut-graph solid, as latmpm-lattice --stl writes
// it: a level set of the capsule/plate union meshed by volumeToMesh.
#pragma once
#include <functional>

#include "geometry/strut_graph.hpp"
#include "mesh/triangle_mesh.hpp"

namespace latmpm {

// `voxel_size_m`: level-set voxel (m); the surface deviates from the exact solid by a small
// fraction of it (volume −0.7 % at 8 voxels per strut radius, second order).
// Samples are placed half a voxel off the round-number planes where plates and flat strut
// ends usually lie, and values within 1/1000 voxel of zero are pushed off zero: a sample
// exactly on the surface makes volumeToMesh put vertices of neighbouring cells on one point,
// which after STL's float rounding gives non-manifold edges and self-intersections.
TriangleMesh strut_graph_surface(const StrutGraph& graph, double voxel_size_m,
                                 const std::function<void(double)>& progress = {});

}  // namespace latmpm
