// Single stages of a step, public so tests can check each transfer on its own
// (conservation, patch tests). A run uses Simulation::step().
#include "mpm/simulation.hpp"
#include "mpm/simulation_impl.hpp"

namespace latmpm::mpm {

void Simulation::stage_particles_to_grid() {
  auto& im = *impl_;
  im.needs_sort = true;  // positions may have been set from outside
  im.arena.execute([&] {
    im.with_solver_shape([&](auto shape) {
      using Shape = decltype(shape);
      im.prepare_grid<Shape>();
      im.scatter<Shape, ScatterAll>();
    });
  });
}

void Simulation::stage_grid_update(Real dt) {
  auto& im = *impl_;
  im.arena.execute([&] {
    im.with_solver_shape([&](auto shape) {
      using Shape = decltype(shape);
      im.add_contact_forces<Shape>();
      im.ddmp_hand_on<Shape>(lane::mass, 7, true);
      im.reactions = update_grid_velocities(im.grid, dt, settings_.gravity, im.body_info);
      im.constrain_boundaries(dt);
      im.ddmp_read_back<Shape>(lane::momentum, 6);
    });
  });
  im.grid_holds_velocity = true;
}

void Simulation::stage_set_grid_velocity(const std::function<Vec3(const Vec3&)>& field) {
  auto& g = impl_->grid;
  constexpr int bw = SparseGrid::block_width;
  for (size_t b = 0; b < g.block_count(); ++b) {
    const auto c = g.coord(b);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          Real* node = g.block(b) + SparseGrid::node_offset(i, j, k);
          const Vec3 v = field(SparseGrid::node_position(c[0] * bw + i, c[1] * bw + j, c[2] * bw + k, settings_.cell_size));
          for (int a = 0; a < 3; ++a) node[lane::momentum + a] = node[lane::force + a] = v[a];
        }
  }
  impl_->grid_holds_velocity = true;
}

void Simulation::stage_grid_to_particles(Real dt) {
  auto& im = *impl_;
  im.arena.execute([&] {
    im.with_solver_shape([&](auto shape) { im.gather<decltype(shape), GatherAll>(dt); });
  });
}

Simulation::GridTotals Simulation::grid_totals() const {
  GridTotals t;
  const auto& g = impl_->grid;
  for (size_t b = 0; b < g.block_count(); ++b)
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
      const Real* node = g.block(b) + n * lane::count;
      t.mass += node[lane::mass];
      const Real scale = impl_->grid_holds_velocity ? node[lane::mass] : Real(1);
      for (int a = 0; a < 3; ++a) t.momentum[a] += scale * node[lane::momentum + a];
    }
  return t;
}

Simulation::Gathered Simulation::gather_from_grid() const {
  const Particles& copy = particles_;
  auto& im = *impl_;
  Gathered out;
  out.velocity.resize(copy.size());
  out.velocity_gradient.resize(copy.size());
  BucketBuffer buffer;
  im.with_solver_shape([&](auto shape) {
    using Shape = decltype(shape);
    constexpr int N = Shape::nodes_per_axis;
    constexpr bool nodal_gradient = has_grid_smoothed_gradient<Shape>::value;
    if constexpr (nodal_gradient)
      ddmp_nodal_velocity_gradient(im.grid, lane::momentum, settings_.cell_size, im.ddmp_nodal);
    for (size_t bi = 0; bi < im.buckets.buckets().size(); ++bi) {
      const Bucket& b = im.buckets.buckets()[bi];
      buffer.attach(b);
      buffer.ddmp_alpha = im.ddmp_partition();
      copy_box_from_grid(b, im.tables[bi], im.grid, buffer);
      if constexpr (nodal_gradient) copy_ddmp_box_from_grid(b, im.tables[bi], im.ddmp_nodal, buffer);
      for (uint32_t p = b.begin; p < b.end; ++p) {
        const auto st = particle_stencil<Shape>(copy, p, settings_.cell_size, buffer);
        Vec3 v = Vec3::Zero();
        Mat3 grad = Mat3::Zero();
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < N; ++j)
            for (int k = 0; k < N; ++k) {
              const Real* node = buffer.data.data() + buffer.offset(st.base[0] + i, st.base[1] + j, st.base[2] + k);
              const Vec3 vi(node[lane::momentum], node[lane::momentum + 1], node[lane::momentum + 2]);
              Real w;
              Vec3 dw;
              if constexpr (uses_domain_vertices<Shape>::value) {  // CPDI1's dense box
                const int e = CpdiBoxStencil::index(i, j, k);
                w = st.w[e], dw = Vec3(st.g[0][e], st.g[1][e], st.g[2][e]);
              } else {
                w = st.w[i][0] * st.w[j][1] * st.w[k][2];
                dw = Vec3(st.dw[i][0] * st.w[j][1] * st.w[k][2], st.w[i][0] * st.dw[j][1] * st.w[k][2],
                          st.w[i][0] * st.w[j][1] * st.dw[k][2]);
              }
              v += w * vi;
              grad += vi * dw.transpose();
            }
        if constexpr (nodal_gradient) {
          Real L[9];
          ddmp_corner_velocity_gradient(st, buffer, L);
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) grad(r, c) += L[r * 3 + c];
        } else if constexpr (has_smoothed_gradient<Shape>::value)
          for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j)
              for (int k = 0; k < N; ++k) {
                const Real* node = buffer.data.data() + buffer.offset(st.base[0] + i, st.base[1] + j, st.base[2] + k);
                const Vec3 vi(node[lane::momentum], node[lane::momentum + 1], node[lane::momentum + 2]);
                grad += vi * st.smoothed[(i * N + j) * N + k].transpose();
              }
        out.velocity[p] = v;
        out.velocity_gradient[p] = grad;
      }
    }
  });
  return out;
}

std::vector<Simulation::GridNode> Simulation::grid_nodes() const {
  const auto& g = impl_->grid;
  constexpr int bw = SparseGrid::block_width;
  std::vector<GridNode> out;
  for (size_t b = 0; b < g.block_count(); ++b) {
    const auto c = g.coord(b);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          GridNode n;
          n.index = {c[0] * bw + i, c[1] * bw + j, c[2] * bw + k};
          const Real* lanes = g.block(b) + SparseGrid::node_offset(i, j, k);
          for (int l = 0; l < lane::count; ++l) n.lanes[size_t(l)] = lanes[l];
          out.push_back(n);
        }
  }
  return out;
}

}  // namespace latmpm::mpm
