// The CGAL types the mesh library's .cpp files share (internal: no public header includes
// this, so CGAL stays inside libs/mesh).
#pragma once
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace latmpm::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Surface = CGAL::Surface_mesh<Point>;

}  // namespace latmpm::cgal
