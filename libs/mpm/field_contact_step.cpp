// The step of a run with multi-field grid contact (field_contact.hpp): USL (Bardenhagen et
// al. 2000 Sec. 3) with each field scattered into lanes of its own, the node update on their
// sum (so boundaries, reactions and the energy sums see what one field would), the contact
// rule between the fields, and each field's points gathered from its lanes. The stages are
// the single-field ones, run once per field with StepContext::active_field selecting the
// field's runs (a bucket run is one body and field, particle_buckets.cpp).
#include <cmath>
#include <stdexcept>

#include "core/errors.hpp"
#include "mpm/settings.hpp"
#include "mpm/step_stages.hpp"

namespace latmpm::mpm {

void validate(const FieldContactSettings& contact, ShapeFunctionKind shape, UpdateScheme scheme,
              const std::string& where) {
  if (!(contact.friction >= 0) || !std::isfinite(contact.friction))
    throw InputError(where, "contact.friction", "must be zero or positive (a Coulomb coefficient)");
  if (!(contact.fill >= 0 && contact.fill <= 1)) throw InputError(where, "contact.fill", "must lie in [0, 1]");
  if (!contact.enabled) return;
  if (shape == ShapeFunctionKind::ddmp || shape == ShapeFunctionKind::cpdi1)
    throw InputError(where, "contact", "grid contact takes linear, ugimp, cpgimp and bspline shapes, not " +
                                           to_string(shape) +
                                           " (its smoothed or vertex-based gradient has no per-field form yet)");
  if (scheme != UpdateScheme::usl)
    throw InputError(where, "contact", "grid contact runs the usl scheme only (this scene sets " + to_string(scheme) + ")");
}

namespace {
// Runs `pass` once per field with that field's lanes in the grid's place.
template <class Pass>
void for_each_field(SolverState& s, StepContext& c, ContactFields& f, Pass&& pass) {
  for (int k = 0; k < f.count; ++k) {
    s.grid.swap_lanes(f.lanes[size_t(k)]);
    c.active_field = k;
    pass(k);
    s.grid.swap_lanes(f.lanes[size_t(k)]);
  }
  c.active_field = -1;
}

template <class Shape>
void step_usl_fields(SolverState& s, StepContext& c, ContactFields& f, Real dt) {
  prepare_grid<Shape>(s, c);
  clear_field_lanes(s.grid, f);
  for_each_field(s, c, f, [&](int) { scatter<Shape, ScatterAll>(s, c); });
  sum_fields_into_grid(s.grid, f);
  update_nodes(s, c, dt);
  apply_field_contact(s.grid, f, dt, c.settings.gravity, c.settings.cell_size);
  c.tallies.assign(c.tallies.size(), empty_tally());
  Real node_increment = 0;  // each field's nodes, whose increments its points receive
  for_each_field(s, c, f, [&](int) {
    node_increment += node_increment_energy(s, c);
    f.pass_tallies.assign(c.tallies.size(), empty_tally());
    gather_buckets<Shape, GatherAll>(s, c, dt, f.pass_tallies);
    for (size_t b = 0; b < c.tallies.size(); ++b) merge_tally(c.tallies[b], f.pass_tallies[b]);
  });
  c.sums.node_increment_energy = node_increment;
  absorb_tallies(s, c, true, true, true);
  c.sums.grid_contact_dissipation = f.dissipated;
}
}  // namespace

void step_with_field_contact(SolverState& s, StepContext& c, ContactFields& fields, Real dt) {
  if (c.penalty_contact) throw std::logic_error("grid contact with penalty rigid bodies is refused when they are added");
  with_solver_shape(c.settings, [&](auto shape) {
    using Shape = decltype(shape);
    if constexpr (Shape::smoothed_gradient || Shape::uses_domain_vertices)
      throw std::logic_error("grid contact with " + to_string(c.settings.shape_function) + " is refused by validate");
    else
      step_usl_fields<Shape>(s, c, fields, dt);
  });
}

}  // namespace latmpm::mpm
