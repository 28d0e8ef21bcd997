// Single stages of a step for tests (simulation_test_access.hpp): the same stage functions
// the step calls (step_stages.hpp), one at a time.
#include "mpm/simulation_test_access.hpp"

#include "mpm/step_stages.hpp"

namespace latmpm::mpm {

void SimulationTestAccess::particles_to_grid(Simulation& sim) {
  SolverState& s = sim.state_;
  StepContext& c = *sim.context_;
  s.needs_sort = true;  // positions may have been set from outside
  c.arena.execute([&] {
    with_solver_shape(c.settings, [&](auto shape) {
      using Shape = decltype(shape);
      prepare_grid<Shape>(s, c);
      scatter<Shape, ScatterAll>(s, c);
    });
  });
}

void SimulationTestAccess::grid_update(Simulation& sim, Real dt) {
  SolverState& s = sim.state_;
  StepContext& c = *sim.context_;
  c.arena.execute([&] {
    with_solver_shape(c.settings, [&](auto shape) {
      using Shape = decltype(shape);
      add_contact_forces<Shape>(s, c);
      ddmp_hand_on<Shape, lane::mass, 7>(s, c, true);
      update_nodes(s, c, dt);
      ddmp_read_back<Shape, lane::momentum, 6>(s, c);
    });
  });
  s.grid_holds_velocity = true;
}

void SimulationTestAccess::set_grid_velocity(Simulation& sim, const std::function<Vec3(const Vec3&)>& field) {
  auto& g = sim.state_.grid;
  const Real h = sim.settings_.cell_size;
  constexpr int bw = SparseGrid::block_width;
  for (size_t b = 0; b < g.block_count(); ++b) {
    const auto c = g.coord(b);
    for (int i = 0; i < bw; ++i)
      for (int j = 0; j < bw; ++j)
        for (int k = 0; k < bw; ++k) {
          Real* node = g.block(b) + SparseGrid::node_offset(i, j, k);
          const Vec3 v = field(SparseGrid::node_position(c[0] * bw + i, c[1] * bw + j, c[2] * bw + k, h));
          for (int a = 0; a < 3; ++a) node[lane::momentum + a] = node[lane::force + a] = v[a];
        }
  }
  sim.state_.grid_holds_velocity = true;
}

void SimulationTestAccess::grid_to_particles(Simulation& sim, Real dt) {
  SolverState& s = sim.state_;
  StepContext& c = *sim.context_;
  c.arena.execute([&] {
    with_solver_shape(c.settings, [&](auto shape) { gather<decltype(shape), GatherAll>(s, c, dt); });
  });
}

SimulationTestAccess::GridTotals SimulationTestAccess::grid_totals(const Simulation& sim) {
  GridTotals t;
  const auto& g = sim.state_.grid;
  for (size_t b = 0; b < g.block_count(); ++b)
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
      const Real* node = g.block(b) + n * lane::count;
      t.mass += node[lane::mass];
      const Real scale = sim.state_.grid_holds_velocity ? node[lane::mass] : Real(1);
      for (int a = 0; a < 3; ++a) t.momentum[a] += scale * node[lane::momentum + a];
    }
  return t;
}

SimulationTestAccess::Gathered SimulationTestAccess::gather_from_grid(const Simulation& sim) {
  const Particles& copy = sim.state_.particles;
  const SolverState& s = sim.state_;
  StepContext& c = *sim.context_;
  const Real h = sim.settings_.cell_size;
  Gathered out;
  out.velocity.resize(copy.size());
  out.velocity_gradient.resize(copy.size());
  BucketBuffer buffer;
  with_solver_shape(c.settings, [&](auto shape) {
    using Shape = decltype(shape);
    constexpr int N = Shape::nodes_per_axis;
    constexpr bool nodal_gradient = Shape::smoothed_on_grid;
    if constexpr (nodal_gradient)
      ddmp_nodal_velocity_gradient(s.grid, lane::momentum, h, c.ddmp_nodal);
    for (size_t bi = 0; bi < s.buckets.buckets().size(); ++bi) {
      const Bucket& b = s.buckets.buckets()[bi];
      buffer.attach(b);
      buffer.ddmp_alpha = c.ddmp_partition();
      copy_box_from_grid(b, c.columns[bi], c.tables[bi], s.grid, buffer);
      if constexpr (nodal_gradient) copy_ddmp_box_from_grid(b, c.columns[bi], c.tables[bi], c.ddmp_nodal, buffer);
      buffer.grid = &s.grid;
      for (uint32_t p = b.begin; p < b.end; ++p) {
        if (c.body_info[size_t(copy.body[p])].marked_once) continue;  // out of the step: their nodes are outside the box
        const auto st = particle_stencil<Shape>(copy, p, h, buffer);
        Vec3 v = Vec3::Zero();
        Mat3 grad = Mat3::Zero();
        if constexpr (Shape::uses_domain_vertices)
          if (st.wide) {  // vertex by vertex from the grid (shape_cpdi.hpp)
            const auto [aw, ax, ay, az] = interpolate_wide<true>(st, s.grid);
            for (int r = 0; r < 3; ++r) {
              v[r] = aw[lane::momentum + r];
              grad(r, 0) = ax[lane::momentum + r], grad(r, 1) = ay[lane::momentum + r], grad(r, 2) = az[lane::momentum + r];
            }
            out.velocity[p] = v;
            out.velocity_gradient[p] = grad;
            continue;
          }
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < N; ++j)
            for (int k = 0; k < N; ++k) {
              const Real* node = buffer.data.data() + buffer.offset(st.base[0] + i, st.base[1] + j, st.base[2] + k);
              const Vec3 vi(node[lane::momentum], node[lane::momentum + 1], node[lane::momentum + 2]);
              Real w;
              Vec3 dw;
              if constexpr (Shape::uses_domain_vertices) {  // CPDI1's dense box
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
            for (int k = 0; k < 3; ++k) grad(r, k) += L[r * 3 + k];
        }
        if constexpr (Shape::per_node_gradient)
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

std::vector<SimulationTestAccess::GridNode> SimulationTestAccess::grid_nodes(const Simulation& sim) {
  const auto& g = sim.state_.grid;
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

void SimulationTestAccess::forget_last_ddmp_find(Simulation& sim) { sim.context_->ddmp_nodal.last_find.layout = 0; }

}  // namespace latmpm::mpm
