#include "optimize/optimisation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/errors.hpp"
#include "optimize/connectivity.hpp"
#include "optimize/mma_step.hpp"

namespace latmpm::optimize {

Real NarrowBandSchedule::threshold(int k) const {
  if (ramp_iterations <= 0) return end;
  return start + (end - start) * std::min<Real>(1, Real(k) / Real(ramp_iterations));
}

Real volume_fraction(const DesignGrid& grid, const std::vector<Real>& density) {
  Real sum = 0;
  for (Real r : density) sum += r;
  return sum * grid.point_volume() / grid.domain_volume();
}

namespace {

// Points in a cell with a face of nodes held in every direction (a component without one
// floats or hangs on a hinge; a symmetry plane holds only its normal): 4 of the cell's 8
// corners, a planar cell's edge counting twice.
std::vector<size_t> clamp_anchors(const DesignGrid& grid, const LoadCase& load_case) {
  std::vector<const Support*> clamps;
  for (const Support& s : load_case.supports)
    if (s.held[0] && s.held[1] && (s.held[2] || grid.planar)) clamps.push_back(&s);
  std::vector<size_t> anchors;
  for (size_t q = 0; q < grid.point_count(); ++q) {
    const Index3 c = grid.cell_of(q);
    int held = 0;
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 node = grid.cell_size * Vec3(c[0] + (corner & 1), c[1] + ((corner >> 1) & 1), c[2] + ((corner >> 2) & 1));
      bool in = false;
      for (const Support* s : clamps) in = in || s->box.contains(node);
      held += in;
    }
    if (held >= 4) anchors.push_back(q);
  }
  return anchors;
}

}  // namespace

OptimisationResult optimise(const DesignGrid& grid, const LoadCase& load_case, Parameterisation& design,
                            const OptimisationSettings& settings,
                            const std::function<void(const IterationRecord&)>& on_iteration) {
  const size_t n = grid.point_count();
  std::vector<size_t> keep;  // loaded points stay simulated
  for (const auto& points : loaded_points(grid, load_case)) keep.insert(keep.end(), points.begin(), points.end());
  const std::vector<size_t> anchors = clamp_anchors(grid, load_case);
  const SimpMaterial& material = settings.material;

  OptimisationResult result;
  Real best_compliance = std::numeric_limits<Real>::infinity();
  std::vector<Real> x = design.initial(), lower, upper, move, rho;
  EquilibriumGuess guess;  // neo-Hookean: the last equilibrium starts the next solve
  design.bounds(lower, upper, move);
  for (int k = 0; k < settings.max_iterations; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    design.start_iteration(k);
    design.densities(x, rho);
    for (size_t q : keep) rho[q] = 1;  // loaded points: solid, not designed
    Real threshold = settings.band.enabled ? settings.band.threshold(k) : 0;
    std::vector<char> mask(n, 1);
    std::vector<Real> masked(n);
    ComplianceResult c;
    // Where the threshold would cut every path from the loads to the supports, or leave a
    // piece the static solve cannot hold, it is lowered for this iteration (by 0.05 at a
    // time, not below the schedule's start).
    // Where even the lowest threshold leaves no solvable band, this iteration fills the whole
    // domain with the weak material (E_min = 1e-9 E, the band's threshold reported as 0).
    bool band = settings.band.enabled;
    bool linear_fallback = false;
    auto lower_threshold = [&] { threshold = std::max(settings.band.start, threshold - 0.05); };
    for (bool solved = false; !solved;) {
      bool joined = true;
      if (band) mask = narrow_band_mask(grid, rho, threshold, keep, anchors, &joined);
      else mask.assign(n, 1);
      const bool lowest = threshold <= settings.band.start;
      if (band && !joined && !lowest) {
        lower_threshold();
        continue;
      }
      for (size_t q = 0; q < n; ++q) masked[q] = mask[q] ? rho[q] : 0;
      SimpMaterial m = material;
      m.weak_ratio = band ? 0 : 1e-9;  // the band's outside is not simulated; without it, weak
      if (linear_fallback) m.model = mpm::MaterialKind::linear_elastic;
      try {
        c = evaluate_compliance(grid, masked, mask, load_case, m, &guess);
        solved = true;
      } catch (const NumericalError&) {
        if (!linear_fallback && m.model != mpm::MaterialKind::linear_elastic) {
          // No nonlinear equilibrium on this band (a mechanism the linear solve's diagonal
          // shift holds, at a huge compliance that steers the design back): this iteration
          // steps on the linear compliance.
          linear_fallback = true;
          ++result.linear_fallbacks;
          continue;
        }
        if (!band) throw;
        if (lowest) band = false, threshold = 0;
        else lower_threshold();
      }
    }
    const Real v = volume_fraction(grid, masked);
    std::vector<Real> d_volume(n);
    for (size_t q = 0; q < n; ++q) d_volume[q] = mask[q] ? grid.point_volume() / grid.domain_volume() : 0;
    for (size_t q : keep) c.gradient[q] = d_volume[q] = 0;

    IterationRecord record{k, c.compliance, v, threshold, 0, c.active_points, c.unknowns, c.newton_iterations, c.load_steps};
    // The design kept: the last one until the schedules end, then the stiffest that meets
    // the volume bound (the band's alternation makes late iterates oscillate).
    const bool schedules_done = design.continuation_done() && (!settings.band.enabled || k >= settings.band.ramp_iterations);
    const bool feasible = v <= settings.volume_fraction * 1.005;
    if (!schedules_done || result.history.empty() || (feasible && c.compliance < best_compliance)) {
      result.density = masked;
      result.active = mask;
      result.x = x;
      if (schedules_done && feasible) best_compliance = c.compliance;
    }

    // Converged: C steady over the last 5 iterations, volume bound met, schedules at their end.
    const auto& h = result.history;
    bool steady = h.size() >= 5;
    for (size_t i = h.size() >= 5 ? h.size() - 5 : 0; steady && i < h.size(); ++i)
      steady = std::abs(h[i].compliance - c.compliance) <= settings.tolerance * c.compliance;
    if (schedules_done && steady && feasible) {
      result.converged = true;
      record.seconds = std::chrono::duration<Real>(std::chrono::steady_clock::now() - t0).count();
      result.history.push_back(record);
      if (on_iteration) on_iteration(record);
      break;
    }

    MmaInput in;
    in.x = x;
    in.objective = c.compliance;
    in.objective_gradient = design.pull_back(x, c.gradient);
    in.constraint = v - settings.volume_fraction;
    in.constraint_gradient = design.pull_back(x, d_volume);
    in.lower = lower;
    in.upper = upper;
    in.move = move;
    x = mma_step(in);
    record.seconds = std::chrono::duration<Real>(std::chrono::steady_clock::now() - t0).count();
    result.history.push_back(record);
    if (on_iteration) on_iteration(record);
  }
  return result;
}

}  // namespace latmpm::optimize
