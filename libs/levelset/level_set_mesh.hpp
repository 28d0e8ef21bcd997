// Level set → triangle surface and enclosed volume.
#pragma once
#include <openvdb/openvdb.h>

#include "mesh/triangle_mesh.hpp"

namespace latmpm {

// The zero iso-surface (openvdb::tools::volumeToMesh, no adaptivity), quads split along their
// shorter diagonal, triangles counter-clockwise seen from outside (outward normals). Metres.
TriangleMesh level_set_to_mesh(const openvdb::FloatGrid& level_set);

// Volume enclosed by the zero iso-surface (m³), openvdb::tools::levelSetVolume.
double level_set_volume(const openvdb::FloatGrid& level_set);

}  // namespace latmpm
