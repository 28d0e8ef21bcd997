#include "mpm/motion_schedule.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace latmpm::mpm {

namespace {
// The index k of the segment [t_k, t_{k+1}) holding t; the last knot's index after it.
size_t segment_of(const std::vector<VelocityKnot>& knots, Real t) {
  const auto after = std::upper_bound(knots.begin(), knots.end(), t,
                                      [](Real time, const VelocityKnot& k) { return time < k.time; });
  return after == knots.begin() ? 0 : size_t(after - knots.begin()) - 1;
}

// V at t inside segment k (its start velocity after the last knot).
Vec3 velocity_in(const std::vector<VelocityKnot>& knots, size_t k, Real t) {
  if (k + 1 >= knots.size()) return knots[k].velocity;
  const Real s = (t - knots[k].time) / (knots[k + 1].time - knots[k].time);
  return knots[k].velocity + s * (knots[k + 1].velocity - knots[k].velocity);
}
}  // namespace

Vec3 MotionSchedule::velocity(Real t) const {
  if (knots.empty()) return Vec3::Zero();
  return velocity_in(knots, segment_of(knots, t), t);
}

Vec3 MotionSchedule::displacement(Real t) const {
  if (knots.empty() || t <= 0) return Vec3::Zero();
  const size_t k = segment_of(knots, t);
  Vec3 d = Vec3::Zero();
  for (size_t j = 0; j < k; ++j)  // whole segments: trapezoids, exact for linear V
    d += Real(0.5) * (knots[j + 1].time - knots[j].time) * (knots[j].velocity + knots[j + 1].velocity);
  // The part of segment k up to t: again a trapezoid, between V(t_k) and V(t).
  d += Real(0.5) * (t - knots[k].time) * (knots[k].velocity + velocity_in(knots, k, t));
  return d;
}

Real MotionSchedule::max_speed() const {
  Real out = 0;
  for (const auto& k : knots) out = std::max(out, k.velocity.norm());
  return out;
}

Vec3 MotionSchedule::first_direction() const {
  for (const auto& k : knots)
    if (k.velocity.norm() > 0) return k.velocity.normalized();
  return Vec3::Zero();
}

void validate(const MotionSchedule& s, const std::string& where, const std::string& field) {
  if (s.knots.empty()) throw InputError(where, field, "needs at least one knot { time, velocity }");
  for (size_t k = 0; k < s.knots.size(); ++k) {
    const std::string knot = field + "[" + std::to_string(k) + "]";
    if (!std::isfinite(s.knots[k].time)) throw InputError(where, knot + ".time", "must be finite");
    if (!s.knots[k].velocity.allFinite()) throw InputError(where, knot + ".velocity", "must be finite");
    if (k == 0 && s.knots[k].time != 0)
      throw InputError(where, knot + ".time", "the first knot must be at time 0 (where the run starts)");
    if (k > 0 && !(s.knots[k].time > s.knots[k - 1].time))
      throw InputError(where, knot + ".time", "must be later than the knot before it (times increase strictly)");
  }
}

}  // namespace latmpm::mpm
