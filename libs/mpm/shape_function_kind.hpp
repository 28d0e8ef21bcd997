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

}  // namespace latmpm::mpm
