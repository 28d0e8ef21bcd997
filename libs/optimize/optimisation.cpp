#include "optimize/optimisation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

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

OptimisationResult optimise(const DesignGrid& grid, const LoadCase& load_case, Parameterisation& design,
                            const OptimisationSettings& settings,
                            const std::function<void(const IterationRecord&)>& on_iteration) {
  const size_t n = grid.point_count();
  std::vector<size_t> keep;  // loaded points stay simulated
  for (const auto& points : loaded_points(grid, load_case)) keep.insert(keep.end(), points.begin(), points.end());
  // Anchors: points in a cell with a node held in every direction (a component without one
  // floats; a symmetry plane holds only its normal).
  std::vector<const Support*> clamps;
  for (const Support& s : load_case.supports)
    if (s.held[0] && s.held[1] && (s.held[2] || grid.planar)) clamps.push_back(&s);
  std::vector<size_t> anchors;
  for (size_t q = 0; q < n; ++q) {
    const Index3 c = grid.cell_of(q);
    bool held = false;
    for (int corner = 0; corner < 8 && !held; ++corner) {
      const Vec3 node = grid.cell_size * Vec3(c[0] + (corner & 1), c[1] + ((corner >> 1) & 1), c[2] + ((corner >> 2) & 1));
      for (const Support* s : clamps) held = held || s->box.contains(node);
    }
    if (held) anchors.push_back(q);
  }
  SimpMaterial material = settings.material;
  material.weak_ratio = settings.band.enabled ? 0 : 1e-9;

  OptimisationResult result;
  std::vector<Real> x = design.initial(), lower, upper, move, rho;
  design.bounds(lower, upper, move);
  for (int k = 0; k < settings.max_iterations; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    design.start_iteration(k);
    design.densities(x, rho);
    for (size_t q : keep) rho[q] = 1;  // loaded points: solid, not designed
    Real threshold = settings.band.enabled ? settings.band.threshold(k) : 0;
    std::vector<char> mask(n, 1);
    if (settings.band.enabled) {
      // Where the threshold would cut every path from the loads to the supports, it is
      // lowered for this iteration (by 0.05 at a time, not below the schedule's start).
      bool joined = false;
      for (;;) {
        mask = narrow_band_mask(grid, rho, threshold, keep, anchors, &joined);
        if (joined || threshold <= settings.band.start) break;
        threshold = std::max(settings.band.start, threshold - 0.05);
      }
    }
    std::vector<Real> masked(n);
    for (size_t q = 0; q < n; ++q) masked[q] = mask[q] ? rho[q] : 0;
    ComplianceResult c = evaluate_compliance(grid, masked, mask, load_case, material);
    const Real v = volume_fraction(grid, masked);
    std::vector<Real> d_volume(n);
    for (size_t q = 0; q < n; ++q) d_volume[q] = mask[q] ? grid.point_volume() / grid.domain_volume() : 0;
    for (size_t q : keep) c.gradient[q] = d_volume[q] = 0;

    result.density = masked;
    result.active = mask;
    result.x = x;
    IterationRecord record{k, c.compliance, v, threshold, 0, c.active_points, c.unknowns};

    // Converged: C steady over the last 5 iterations, volume bound met, schedules at their end.
    const auto& h = result.history;
    const bool schedules_done = design.continuation_done() && (!settings.band.enabled || k >= settings.band.ramp_iterations);
    bool steady = h.size() >= 5;
    for (size_t i = h.size() >= 5 ? h.size() - 5 : 0; steady && i < h.size(); ++i)
      steady = std::abs(h[i].compliance - c.compliance) <= settings.tolerance * c.compliance;
    if (schedules_done && steady && v <= settings.volume_fraction * 1.005) {
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
