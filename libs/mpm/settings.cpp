#include "mpm/settings.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace latmpm::mpm {

void validate(const Settings& s, const std::string& where) {
  auto positive = [](Real v) { return v > 0 && std::isfinite(v); };
  if (!positive(s.cell_size)) throw InputError(where, "cell_size", "must be a positive length");
  if (!(s.cfl > 0 && s.cfl <= 1)) throw InputError(where, "cfl", "must lie in (0, 1]");
  if (!(s.flip_blend >= 0 && s.flip_blend <= 1))
    throw InputError(where, "flip_blend", "must lie in [0, 1] (0 = PIC, 1 = FLIP)");
  if (!(s.fixed_time_step >= 0) || !std::isfinite(s.fixed_time_step))
    throw InputError(where, "time_step", "must be a non-negative time");
  if (!(s.max_time_step >= 0) || !std::isfinite(s.max_time_step))
    throw InputError(where, "max_time_step", "must be a non-negative time");
  if (s.null_space_filter != NullSpaceFilter::none && s.shape_function == ShapeFunctionKind::cpdi1)
    throw InputError(where, "null_space_filter", "is not available for cpdi1 (its stencils are not tensor products)");
  if (s.null_space_filter_every < 1) throw InputError(where, "null_space_filter_every", "must be at least 1 (steps)");
  if (!(s.ddmp_alpha_peak > 0 && s.ddmp_alpha_peak <= 1))
    throw InputError(where, "ddmp_alpha_peak", "must lie in (0, 1]");
  if (!positive(s.ddmp_alpha_exponent)) throw InputError(where, "ddmp_alpha_exponent", "must be positive");
  if (!(s.ddmp_small_mass_fraction >= 0 && s.ddmp_small_mass_fraction < 1))
    throw InputError(where, "ddmp_small_mass_fraction", "must lie in [0, 1)");
  // ≤ 1: the stable step is the material's; the zig-zag's stiffness is then at most linear MPM's.
  if (!(s.ddmp_stabilization >= 0 && s.ddmp_stabilization <= 1))
    throw InputError(where, "ddmp_stabilization", "must lie in [0, 1] (a fraction of the body's elastic moduli)");
  // A study option of DDMP's grid form: elsewhere it would be silently ignored.
  if (s.ddmp_subpoints && !(s.shape_function == ShapeFunctionKind::ddmp && s.ddmp_on_grid))
    throw InputError(where, "ddmp_subpoints", "needs shape ddmp with ddmp_on_grid");
  // The stabilization is the grid form's (ddmp_stabilization.hpp); the default β too.
  if (s.shape_function == ShapeFunctionKind::ddmp && s.ddmp_stabilization > 0 && (!s.ddmp_on_grid || s.ddmp_subpoints))
    throw InputError(where, "ddmp_stabilization",
                     "needs DDMP on the grid without sub-points (ddmp_on_grid = true, ddmp_subpoints = false) or 0");
  if (!positive(s.mass_scaling)) throw InputError(where, "mass_scaling", "must be positive");
  if (!s.gravity.allFinite()) throw InputError(where, "gravity", "must be finite");
  if (!(s.record_layer_thickness >= 0)) throw InputError(where, "record_layer_thickness", "must not be negative");
  if (s.threads < 0) throw InputError(where, "threads", "must not be negative (0 = all cores)");
  if (!(s.min_jacobian >= 0 && s.min_jacobian < 1)) throw InputError(where, "min_jacobian", "must lie in [0, 1)");
  if (!positive(s.runaway_energy_factor)) throw InputError(where, "runaway_energy_factor", "must be positive");
  validate(s.field_contact, s.shape_function, s.scheme, where);
}

}  // namespace latmpm::mpm
