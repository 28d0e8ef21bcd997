// Exact CSG of a strut graph as a STEP file, for CAD users: every strut a cylinder (plus a
// sphere at each round end), every plate a box, fused into one solid by OpenCASCADE through
// gmsh. Coordinates in millimetres. Slow for large lattices (DEBIAN-STACK.md: a 604-strut
// fuse took minutes and gigabytes); the level-set STL is the fast surface.
#pragma once
#include <cstddef>
#include <string>

#include "geometry/strut_graph.hpp"

namespace latmpm {

struct StepReport {
  size_t solids = 0;   // primitives fused
  double seconds = 0;  // wall time of building, fusing and writing
};

// Writes `path` (any name; the format is always STEP). `verbose`: say on stderr when the
// (possibly long) fuse starts. gmsh's and OpenCASCADE's own messages are silenced.
// Throws InputError(path, ...) when gmsh fails.
StepReport write_step(const StrutGraph& graph, const std::string& path, bool verbose = false);

// What a STEP file holds, measured exactly by OpenCASCADE: for checking an export.
struct StepContents {
  size_t solids = 0;  // separate 3D bodies (1 for a fused, connected specimen)
  double volume = 0;  // m³, total (the file is read in millimetres)
};
StepContents read_step_contents(const std::string& path);

}  // namespace latmpm
