// STL files (binary and ASCII) to and from TriangleMesh.
//
// Binary or ASCII is decided by the file size, never by the word "solid": a binary file is
// exactly 84 + 50 × count bytes (count = the uint32 at byte 80), and CAD exports write binary
// files whose 80-byte header starts with "solid". Anything else starting with "solid" is
// read as ASCII. STL stores single-precision coordinates; ASCII values are rounded to float
// as well, so the ASCII and binary files of one mesh read back identical.
#pragma once
#include <string>

#include "mesh/triangle_mesh.hpp"

namespace latmpm {

enum class StlEncoding { binary, ascii };

// Writes `mesh` (metres) with coordinates divided by `metres_per_unit` (0.001 for a file in
// millimetres). Normals are computed from the vertex order (counter-clockwise = outward).
// Throws InputError(path, ...) if the file cannot be written or the mesh has invalid indices
// or non-finite coordinates.
void write_stl(const TriangleMesh& mesh, const std::string& path, double metres_per_unit,
               StlEncoding encoding = StlEncoding::binary);

// Reads a binary or ASCII STL whose coordinates are in units of `metres_per_unit` metres and
// returns the mesh in metres. Vertices with identical coordinates are merged (STL repeats
// them per triangle), so the result has connectivity for the mesh checks. Stored normals
// are ignored (the vertex order defines the orientation). Throws InputError naming the file
// and what is wrong: empty, truncated, not an STL, no triangles, NaN/Inf coordinates (with
// the triangle index), malformed ASCII (with the line number).
TriangleMesh read_stl(const std::string& path, double metres_per_unit);

// As read_stl, also reporting which encoding the file had.
TriangleMesh read_stl(const std::string& path, double metres_per_unit, StlEncoding* encoding);

}  // namespace latmpm
