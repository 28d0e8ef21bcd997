// The shape functions the static solver offers: those of libs/mpm with a gradient in the
// reference configuration (all but DDMP, whose modified gradient lives on the deforming
// grid). Dispatch like mpm::with_shape_function, with DDMP refused as input.
#pragma once
#include <type_traits>

#include "core/errors.hpp"
#include "mpm/shape_functions.hpp"

namespace latmpm::statics {

template <class F>
void with_static_shape(mpm::ShapeFunctionKind kind, F&& f) {
  mpm::with_shape_function(kind, [&](auto policy) {
    if constexpr (std::is_same_v<decltype(policy), mpm::DdmpShape>)
      throw InputError("static solver", "shape_function",
                       "ddmp has no reference-configuration gradient; use linear, ugimp, cpgimp, "
                       "bspline2 or bspline3");
    else if constexpr (std::is_same_v<decltype(policy), mpm::CpdiShape>)
      throw InputError("static solver", "shape_function",
                       "cpdi1 is not offered by the static solver; use linear, ugimp, cpgimp, bspline2 "
                       "or bspline3");
    else
      f(policy);
  });
}

}  // namespace latmpm::statics
