// Dispatch over the closed set of shape functions: one switch per stage, outside the
// particle loops, which are compiled once per shape. Adding a shape function: a header
// like shape_bspline.hpp with a policy struct, an enum value, one case here and its row (name,
// default CFL) in names.cpp (docs/architecture.md, "A shape function").
#pragma once
#include <utility>

#include "mpm/shape_bspline.hpp"
#include "mpm/shape_cpdi.hpp"
#include "mpm/shape_ddmp.hpp"
#include "mpm/shape_function_kind.hpp"
#include "mpm/shape_gimp.hpp"
#include "mpm/shape_linear.hpp"

namespace latmpm::mpm {

// Calls f(Shape{}) with the policy type of `kind`.
template <class F>
decltype(auto) with_shape_function(ShapeFunctionKind kind, F&& f) {
  switch (kind) {
    case ShapeFunctionKind::linear: return f(LinearShape{});
    case ShapeFunctionKind::ugimp: return f(UgimpShape{});
    case ShapeFunctionKind::cpgimp: return f(CpgimpShape{});
    case ShapeFunctionKind::bspline2: return f(Bspline2Shape{});
    case ShapeFunctionKind::bspline3: return f(Bspline3Shape{});
    case ShapeFunctionKind::ddmp: return f(DdmpShape{});
    case ShapeFunctionKind::cpdi1: return f(CpdiShape{});
  }
  return f(LinearShape{});
}

}  // namespace latmpm::mpm
