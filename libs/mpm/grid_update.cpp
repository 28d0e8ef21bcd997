#include "mpm/grid_update.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace latmpm::mpm {

namespace {
template <class Fn>
void for_each_block(SparseGrid& grid, Fn&& fn) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, grid.block_count(), 8), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t b = r.begin(); b < r.end(); ++b) fn(b, grid.block(b));
  });
}

int constrained_body(const Real* node) { return int(node[lane::constraint]) - 1; }
}  // namespace

std::vector<Real> update_grid_velocities(SparseGrid& grid, Real dt, const Vec3& gravity,
                                         const std::vector<BodyInfo>& bodies) {
  const size_t nb = bodies.size();
  // Per block and body partial sums (force x, y, z and power), added in block order
  // afterwards: deterministic.
  std::vector<Real> rows(grid.block_count() * nb * 4, 0);
  auto add_force = [&](size_t b, int body, const Vec3& r) {
    Real* row = rows.data() + 4 * (b * nb + size_t(body));
    for (int a = 0; a < 3; ++a) row[a] += r[a];
  };
  auto add_power = [&](size_t b, int body, Real power) { rows[4 * (b * nb + size_t(body)) + 3] += power; };
  const Real inv_dt = 1 / dt;
  for_each_block(grid, [&](size_t b, Real* block) {
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
      Real* node = block + n * lane::count;
      const Real m = node[lane::mass];
      const int body = constrained_body(node);
      if (!(m > 0)) {
        // A held node without mass still moves with its body, and any force on it acts on the
        // body (its reaction). DDMP's such nodes next to material have handed their force on
        // and have their velocity read back afterwards (ddmp_grid.hpp, small-mass nodes).
        Vec3 v = Vec3::Zero();
        if (body >= 0 && !bodies[size_t(body)].hold_slip) {
          v = bodies[size_t(body)].velocity;
          const Vec3 r = -Vec3(node[4], node[5], node[6]);
          add_force(b, body, r);
          add_power(b, body, r.dot(v));
        }
        for (int c = 0; c < 3; ++c) node[lane::momentum + c] = v[c], node[lane::force + c] = 0;
        continue;
      }
      const Vec3 p(node[1], node[2], node[3]);
      const Vec3 f = Vec3(node[4], node[5], node[6]) + m * gravity;
      const Vec3 v_old = p / m;
      Vec3 v_new;
      if (body >= 0 && bodies[size_t(body)].hold_slip) {
        // Roller: the free update without its component along the held face's normal.
        const Vec3& normal = bodies[size_t(body)].hold_outward;
        v_new = v_old + dt / m * f;
        v_new -= v_new.dot(normal) * normal;
        const Vec3 r = (m * v_new - p) * inv_dt - f;
        add_force(b, body, r);
      } else if (body >= 0) {
        v_new = bodies[size_t(body)].velocity;
        const Vec3 r = (m * v_new - p) * inv_dt - f;
        add_force(b, body, r);
        add_power(b, body, r.dot(v_new));
      } else {
        v_new = v_old + dt / m * f;
      }
      for (int c = 0; c < 3; ++c) {
        node[lane::momentum + c] = v_new[c];
        node[lane::force + c] = v_new[c] - v_old[c];
      }
    }
  });
  return rows;
}

std::vector<Real> node_increment_energy_rows(SparseGrid& grid) {
  std::vector<Real> rows(grid.block_count(), 0);
  for_each_block(grid, [&](size_t b, Real* block) {
    Real sum = 0;
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
      const Real* node = block + n * lane::count;
      const Real m = node[lane::mass];
      if (!(m > 0)) continue;
      const Real dx = node[lane::force], dy = node[lane::force + 1], dz = node[lane::force + 2];
      sum += Real(0.5) * m * (dx * dx + dy * dy + dz * dz);
    }
    rows[b] = sum;
  });
  return rows;
}

Reactions reactions_from_sums(const std::vector<Real>& sums) {
  const size_t nb = sums.size() / 4;
  Reactions out{std::vector<Vec3>(nb), std::vector<Real>(nb)};
  for (size_t k = 0; k < nb; ++k) {
    out.force[k] = Vec3(sums[4 * k], sums[4 * k + 1], sums[4 * k + 2]);
    out.power[k] = sums[4 * k + 3];
  }
  return out;
}

void grid_velocity_from_momentum(SparseGrid& grid, int from, int to, const std::vector<BodyInfo>& bodies) {
  for_each_block(grid, [&](size_t, Real* block) {
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
      Real* node = block + n * lane::count;
      const Real m = node[lane::mass];
      const int body = constrained_body(node);
      Vec3 v = Vec3::Zero();
      if (body >= 0 && bodies[size_t(body)].hold_slip) {
        const Vec3& normal = bodies[size_t(body)].hold_outward;
        if (m > 0) v = Vec3(node[from], node[from + 1], node[from + 2]) / m;
        v -= v.dot(normal) * normal;
      } else if (body >= 0) {
        v = bodies[size_t(body)].velocity;
      } else if (m > 0) {
        v = Vec3(node[from], node[from + 1], node[from + 2]) / m;
      }
      for (int c = 0; c < 3; ++c) node[to + c] = v[c];
    }
  });
}

void clear_grid_lanes(SparseGrid& grid, int first, int count) {
  for_each_block(grid, [&](size_t, Real* block) {
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n)
      for (int c = first; c < first + count; ++c) block[n * lane::count + c] = 0;
  });
}

void clear_grid(SparseGrid& grid) { clear_grid_lanes(grid, 0, lane::count); }

}  // namespace latmpm::mpm
