#include "mpm/rigid_body.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

void validate(const RigidBodySettings& b, const std::string& where) {
  const std::string key = "rigid_bodies." + b.name + ".";
  if (b.shape == RigidShape::box) {
    if (!b.box_min.allFinite() || !b.box_max.allFinite()) throw InputError(where, key + "min", "must be finite");
    for (int a = 0; a < 3; ++a)
      if (!(b.box_max[a] > b.box_min[a]))
        throw InputError(where, key + "max", "must exceed min along every axis (an empty box)");
  } else {
    if (!b.plane_point.allFinite()) throw InputError(where, key + "point", "must be finite");
    if (!b.plane_normal.allFinite() || !(b.plane_normal.norm() > 0))
      throw InputError(where, key + "normal", "must be a non-zero direction");
  }
  if (!b.velocity.allFinite()) throw InputError(where, key + "velocity", "must be finite");
  if (b.motion == RigidMotion::free && !(b.mass > 0 && std::isfinite(b.mass)))
    throw InputError(where, key + "mass", "a free rigid body needs a positive mass");
  if (b.motion == RigidMotion::fixed && b.velocity != Vec3::Zero())
    throw InputError(where, key + "velocity", "a fixed rigid body stays at rest: its velocity must be zero");
  if (b.motion == RigidMotion::scheduled) {
    validate(b.schedule, where, key + "schedule");
    if (b.velocity != b.schedule.velocity(0))
      throw InputError(where, key + "velocity", "a scheduled body's velocity is its schedule's: leave it out");
  } else if (!b.schedule.empty()) {
    throw InputError(where, key + "schedule", "only a scheduled body (motion = \"scheduled\") takes a schedule");
  }
  if (!(b.contact_stiffness >= 0 && std::isfinite(b.contact_stiffness)))
    throw InputError(where, key + "contact.stiffness", "must be positive (or 0 for the default)");
  if (!(b.friction >= 0)) throw InputError(where, key + "contact.friction", "must be 0 or positive");
}

bool rigid_body_contains(const RigidBodySettings& b, const Vec3& d, const Vec3& x, Real h) {
  // The node's support, the open cube |x − x_i| < h per axis, must overlap the body: exactly
  // the nodes a heavy-particle plate of the same extent touches (its points' domains end at
  // its surface, and their stencils reach one cell beyond). A node exactly one cell away is
  // not coupled yet (weight zero), so a body touching a surface that lies on a node plane
  // picks up that plane at once and the next one as soon as it moves.
  const Real reach = h * (1 - 1e-9);
  if (b.shape == RigidShape::box) {
    for (int a = 0; a < 3; ++a)
      if (!(x[a] > b.box_min[a] + d[a] - reach && x[a] < b.box_max[a] + d[a] + reach)) return false;
    return true;
  }
  return (x - b.plane_point - d).dot(b.plane_normal.normalized()) < reach;
}

bool rigid_body_may_reach(const RigidBodySettings& b, const Vec3& d, const Vec3& lo, const Vec3& hi, Real h) {
  const Real reach = h * (1 + 1e-6);  // wider than rigid_body_contains' h (1 − 1e-9)
  if (b.shape == RigidShape::box) {
    for (int a = 0; a < 3; ++a)
      if (!(hi[a] > b.box_min[a] + d[a] - reach && lo[a] < b.box_max[a] + d[a] + reach)) return false;
    return true;
  }
  // The smallest signed distance of the box's corners from the plane.
  const Vec3 n = b.plane_normal.normalized();
  Real nearest = 0;
  for (int a = 0; a < 3; ++a)
    nearest += std::min(n[a] * (lo[a] - b.plane_point[a] - d[a]), n[a] * (hi[a] - b.plane_point[a] - d[a]));
  return nearest < reach;
}

namespace {
// Calls fn(block, node) for every node with mass whose support overlaps the body and that no
// other body holds (constraint lane 0, or this body's marker), after claiming it; block by
// block in parallel. Blocks the body cannot reach are skipped whole: on a lattice the plates
// touch a few percent of the blocks, and testing every node cost 8 % of a step (T2P30).
template <class Fn>
void for_each_claimed_node(SparseGrid& grid, Real h, const RigidBodySettings& body, const RigidBodyState& state,
                           Real marker, Fn&& fn) {
  constexpr int bw = SparseGrid::block_width;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, grid.block_count(), 8), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t b = r.begin(); b < r.end(); ++b) {
      const auto c = grid.coord(b);
      const Vec3 lo = SparseGrid::node_position(c[0] * bw, c[1] * bw, c[2] * bw, h);
      const Vec3 hi = SparseGrid::node_position(c[0] * bw + bw - 1, c[1] * bw + bw - 1, c[2] * bw + bw - 1, h);
      if (!rigid_body_may_reach(body, state.displacement, lo, hi, h)) continue;
      Real* block = grid.block(b);
      for (int i = 0; i < bw; ++i)
        for (int j = 0; j < bw; ++j)
          for (int k = 0; k < bw; ++k) {
            Real* node = block + SparseGrid::node_offset(i, j, k);
            const Real taken = node[lane::constraint];
            if (!(node[lane::mass] > 0) || (taken != 0 && taken != marker)) continue;
            const Vec3 x = SparseGrid::node_position(c[0] * bw + i, c[1] * bw + j, c[2] * bw + k, h);
            if (!rigid_body_contains(body, state.displacement, x, h)) continue;
            node[lane::constraint] = marker;
            fn(b, node);
          }
    }
  });
}
}  // namespace

std::vector<Real> couple_rigid_body(SparseGrid& grid, Real h, Real dt, const RigidBodySettings& body, const RigidBodyState& state,
                       Real marker) {
  std::vector<Vec3> block_force(grid.block_count(), Vec3::Zero());
  const Vec3& V = state.velocity;
  for_each_claimed_node(grid, h, body, state, marker, [&](size_t b, Real* node) {
    const Real m = node[lane::mass];
    Vec3 change;
    for (int a = 0; a < 3; ++a) {
      change[a] = V[a] - node[lane::momentum + a];
      node[lane::momentum + a] = V[a];
      node[lane::force + a] += change[a];  // Δv = V − v_old
    }
    block_force[b] += (m / dt) * change;
  });
  std::vector<Real> rows(3 * grid.block_count());
  for (size_t b = 0; b < grid.block_count(); ++b)
    for (int a = 0; a < 3; ++a) rows[3 * b + size_t(a)] = block_force[b][a];
  return rows;
}

void impose_rigid_velocity(SparseGrid& grid, Real h, int lane, const RigidBodySettings& body,
                           const RigidBodyState& state, Real marker) {
  for_each_claimed_node(grid, h, body, state, marker, [&](size_t, Real* node) {
    for (int a = 0; a < 3; ++a) node[lane + a] = state.velocity[a];
  });
}

void advance_rigid_body(const RigidBodySettings& body, RigidBodyState& s, const Vec3& reaction,
                        const Vec3& gravity, Real dt) {
  s.reaction = reaction;
  s.work += dt * reaction.dot(s.velocity);
  s.time += dt;
  if (body.motion == RigidMotion::fixed) {  // at rest: no displacement, not even round-off
    s.velocity = Vec3::Zero();
    return;
  }
  if (body.motion == RigidMotion::driven) {
    s.velocity = body.velocity;
    s.displacement += dt * body.velocity;
    return;
  }
  if (body.motion == RigidMotion::scheduled) {  // exact: D(t) in closed form, no sum of steps
    s.velocity = body.schedule.velocity(s.time);
    s.displacement = body.schedule.displacement(s.time);
    return;
  }
  // The specimen pushes the body with −reaction (Newton's third law).
  const Vec3 acceleration = (body.gravity ? gravity : Vec3::Zero()) - reaction / body.mass;
  const Vec3 v_old = s.velocity;
  s.velocity = v_old + dt * acceleration;
  s.displacement += (dt / 2) * (v_old + s.velocity);
}

Real prescribed_max_speed(const RigidBodySettings& body) {
  return body.motion == RigidMotion::scheduled ? body.schedule.max_speed() : body.velocity.norm();
}

Real rigid_kinetic_energy(const RigidBodySettings& body, const RigidBodyState& s) {
  return body.motion == RigidMotion::free ? Real(0.5) * body.mass * s.velocity.squaredNorm() : Real(0);
}

Real rigid_potential_energy(const RigidBodySettings& body, const RigidBodyState& s, const Vec3& gravity) {
  if (body.motion != RigidMotion::free || !body.gravity) return 0;
  return -body.mass * gravity.dot(s.displacement);
}

}  // namespace latmpm::mpm
