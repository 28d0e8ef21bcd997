// The closed set of shape functions the solver offers, and their names in scenes.
#pragma once
#include <string>
#include <vector>

namespace latmpm::mpm {

enum class ShapeFunctionKind {
  linear,     // tent functions of the original MPM (8-node stencil)
  ugimp,      // GIMP with a particle domain of fixed size (the paper's "GIMP"; 27 nodes)
  cpgimp,     // GIMP with the domain stretched by the diagonal of F (64-node stencil)
  bspline2,   // quadratic B-spline (27 nodes)
  bspline3,   // cubic B-spline (64 nodes)
  ddmp,       // dual domain MPM: linear S, modified gradient ∇̄S (Paper A Eq. 7; 64 nodes)
  cpdi1,      // CPDI1 over hexahedral domains convected with F (Paper B Eq. 7; 64 nodes)
};

// "linear", "ugimp", "cpgimp", "bspline2", "bspline3", "ddmp", "cpdi1".
std::string to_string(ShapeFunctionKind kind);
// Every shape function's name, in the kinds' order (names.cpp: the one table).
std::vector<std::string> shape_function_names();
// Inverse of to_string; throws InputError(where, field, ...) for an unknown name.
ShapeFunctionKind parse_shape_function(const std::string& name, const std::string& where = "",
                                       const std::string& field = "");

// The CFL number a run takes unless it sets cfl or dt: per shape function, the largest of 0.3,
// 0.5, 0.6 ... 1.0 up to which paper A's column (cell 0.4 mm; for uGIMP also the QUICK T2P30
// lattice) finished with its load within 1 % of the run at 0.3, measured (docs/tradeoff.md,
// "Time step"; pipelines/tradeoff/cfl-matrix.sh); the B-splines' also on a metal lattice cell
// (names.cpp). The step is dt = cfl · h / max_p(c_p + |v_p|),
// adapted every step (Settings). Kept in the shape's row of the name table (names.cpp).
double default_cfl(ShapeFunctionKind shape);

}  // namespace latmpm::mpm
