// The null-space filter (null_space_filter.hpp): a body's F⁻¹ projected onto the gradients of
// the grid's fields, by a sparse direct solve of the normal equations.
#include "mpm/null_space_filter.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_map>

#include <Eigen/CholmodSupport>

#include "core/blas_threads.hpp"
#include "core/errors.hpp"
#include "mpm/rigid_contact.hpp"
#include "mpm/sparse_grid.hpp"
#include "mpm/step_stages.hpp"

namespace latmpm::mpm {

void project_onto_grid_gradients(const Particles& ps, const std::vector<uint32_t>& points, ShapeFunctionKind shape,
                                 Real h, PointValues& tensors, const std::vector<Vec3>* anchor) {
  // Per point its nodes, gradients ∇S_Ip and (anchored only) weights S_Ip (entries first[n] ..
  // first[n + 1]); a node is keyed by the grid's own packing of three coordinates
  // (SparseGrid::block_key). Without an anchor a node enters where the gradient is non-zero,
  // with one where the weight is too.
  std::unordered_map<uint64_t, int> index;
  std::vector<uint32_t> first{0};
  std::vector<int> node;
  std::vector<Vec3> gradient;
  std::vector<Real> weight;
  size_t stencil = 1;  // the nodes a point's gradients can reach: N³
  with_shape_function(shape, [&](auto policy) {
    using Shape = decltype(policy);
    if constexpr (Shape::uses_domain_vertices) {
      throw InputError("", "null_space_filter", "is not available for cpdi1 (its stencils are not tensor products)");
    } else {
      // DDMP: its force takes the linear gradients plus a smoothed part on the grid
      // (shape_ddmp.hpp); the filter takes the linear ones.
      using Weights = std::conditional_t<Shape::smoothed_gradient, LinearShape, Shape>;
      constexpr int N = Weights::nodes_per_axis;
      stencil = N * N * N;
      for (uint32_t p : points) {
        const auto st = make_stencil<Weights>(ps.position[p], stencil_half_size<Weights>(ps, p, h), 1 / h);
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < N; ++j)
            for (int k = 0; k < N; ++k) {
              const Vec3 g(st.dw[i][0] * st.w[j][1] * st.w[k][2], st.w[i][0] * st.dw[j][1] * st.w[k][2],
                           st.w[i][0] * st.w[j][1] * st.dw[k][2]);
              const Real w = st.w[i][0] * st.w[j][1] * st.w[k][2];
              if (!(g.squaredNorm() > 0) && !(anchor && w > 0)) continue;
              const auto it = index.try_emplace(
                  SparseGrid::block_key(st.base[0] + i, st.base[1] + j, st.base[2] + k), int(index.size())).first;
              node.push_back(it->second);
              gradient.push_back(g);
              if (anchor) weight.push_back(w);
            }
        first.push_back(uint32_t(node.size()));
      }
    }
  });
  const int nodes = int(index.size());
  if (nodes == 0) return;
  // The mass-weighted mean is the gradient of a linear field, which every shape reproduces:
  // it is kept as it is and only the rest projected, so a uniform F (a body at rest) comes
  // back to the last bit whatever the solve's round-off and its regularisation below.
  std::array<Real, 9> mean{};
  Real mass = 0;
  for (size_t n = 0; n < points.size(); ++n) {
    const Real m = ps.mass[points[n]];
    mass += m;
    for (int k = 0; k < 9; ++k) mean[k] += m * tensors[n][k];
  }
  for (int k = 0; k < 9; ++k) mean[k] /= mass;
  for (auto& row : tensors)
    for (int k = 0; k < 9; ++k) row[k] -= mean[k];
  // The anchors less the same linear field, A x_p with A the mean: what is left is fitted
  // (a body at rest, X_p = x_p and F = I, leaves nothing and comes back to the last bit too).
  std::vector<Vec3> values;
  const Real anchor_weight = reference_map_weight / (h * h);
  if (anchor) {
    values.resize(points.size());
    Mat3 a;
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) a(r, k) = mean[3 * r + k];
    for (size_t n = 0; n < points.size(); ++n) values[n] = (*anchor)[n] - a * ps.position[points[n]];
  }
  // K = Gᵀ M G (its lower triangle: the factorisation reads no more) and the right-hand sides
  // Gᵀ M T (column a: component a of X). K is summed from batches of about 4M entries: a point
  // adds up to N(N + 1)/2 of them for its N stencil nodes (uGIMP 378, bspline3 2080), so one
  // list for all of a paper-size lattice's points held ~1 GB.
  Eigen::SparseMatrix<Real> K(nodes, nodes);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nodes, 3);
  std::vector<Eigen::Triplet<Real>> entries;
  const size_t batch = std::max<size_t>(1, (size_t(1) << 22) / (stencil * (stencil + 1) / 2));
  for (size_t start = 0; start < points.size(); start += batch) {
    entries.clear();
    for (size_t n = start; n < std::min(points.size(), start + batch); ++n) {
      const Real m = ps.mass[points[n]];
      for (uint32_t e = first[n]; e < first[n + 1]; ++e) {
        for (uint32_t f = first[n]; f < first[n + 1]; ++f)
          if (node[f] >= node[e])
            entries.emplace_back(node[f], node[e],
                                 m * (gradient[e].dot(gradient[f]) +
                                      (anchor ? anchor_weight * weight[e] * weight[f] : Real(0))));
        for (int a = 0; a < 3; ++a)
          rhs(node[e], a) += m * Vec3(tensors[n][3 * a], tensors[n][3 * a + 1], tensors[n][3 * a + 2]).dot(gradient[e]);
        if (anchor)
          for (int a = 0; a < 3; ++a) rhs(node[e], a) += m * anchor_weight * weight[e] * values[n][a];
      }
    }
    Eigen::SparseMatrix<Real> part(nodes, nodes);
    part.setFromTriplets(entries.begin(), entries.end());
    K = start == 0 ? std::move(part) : Eigen::SparseMatrix<Real>(K + part);
  }
  entries = {};
  // K is singular (a constant has no gradient): 1e-9 of each node's own diagonal makes it
  // definite and touches nothing a gradient sees beyond that (a node at the edge of a
  // B-spline's support has a diagonal far below the others').
  for (int i = 0; i < nodes; ++i) K.coeffRef(i, i) *= 1 + 1e-9;
  // CHOLMOD's supernodal Cholesky (SuiteSparse): on a paper-size lattice (~1e5 nodes, up to
  // 125 neighbours each with uGIMP) it factorises several times faster than a simplicial
  // LDLᵀ. Ordered by AMD alone: CHOLMOD's default also tries METIS, which there took longer
  // than the factorisation it saved (docs/solver.md, "Null-space filter"). Its own printing is
  // off: a failure is this function's one NumericalError, not CHOLMOD's warning beside it.
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<Real>, Eigen::Lower> solver;
  solver.cholmod().print = 0;
  solver.cholmod().nmethods = 1;
  solver.cholmod().method[0].ordering = CHOLMOD_AMD;
  const auto failed = [&] {
    return solver.info() != Eigen::Success || solver.cholmod().status != CHOLMOD_OK;
  };
  solver.analyzePattern(K);
  if (failed()) throw NumericalError("null-space filter: CHOLMOD could not order the grid's gradient system");
  Eigen::MatrixXd u;  // column a: X_a at the nodes
  {
    const auto threads = BlasThreadLimit::for_flops(solver.cholmod().fl);
    solver.factorize(K);
    if (failed()) throw NumericalError("null-space filter: the grid's gradient system did not factorise");
    u = solver.solve(rhs);
    if (failed()) throw NumericalError("null-space filter: CHOLMOD's solve failed");
  }
  // Σ_p m_p T̃_p = Σ_p m_p T_p holds for the exact projection (here: the rest sums to zero);
  // the regularisation and round-off leave a difference, which a constant tensor (the
  // gradient of a linear field) removes; then the mean goes back. Anchored, the mean is
  // fitted too (a uniform drift of F from the positions is one to remove): only the mean goes
  // back.
  std::array<Real, 9> kept{};
  for (size_t n = 0; n < points.size(); ++n) {
    tensors[n] = {};
    for (uint32_t e = first[n]; e < first[n + 1]; ++e)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) tensors[n][3 * a + b] += u(node[e], a) * gradient[e][b];
    for (int k = 0; k < 9; ++k) kept[k] += ps.mass[points[n]] * tensors[n][k];
  }
  for (auto& row : tensors)
    for (int k = 0; k < 9; ++k) row[k] += mean[k] - (anchor ? Real(0) : kept[k] / mass);
}

bool rigid_body_presses(const RigidBodySettings& body, const RigidBodyState& state, size_t index,
                        const Particles& ps, int32_t b, Real h) {
  if (body.coupling == RigidCoupling::penalty) {
    if (ps.contact_body.empty()) return false;
    for (size_t p = 0; p < ps.size(); ++p)
      if (ps.body[p] == b && ps.contact_body[p] == int32_t(index)) return true;
    return false;
  }
  for (size_t p = 0; p < ps.size(); ++p)
    if (ps.body[p] == b &&
        probe_contact(body, state.displacement, ps.position[p], ps.half_size0[p].cast<Real>() + Vec3::Constant(h))
            .penetrates)
      return true;
  return false;
}

bool near_rigid_surface(const RigidBodySettings& body, const RigidBodyState& state, const Vec3& x, Real h) {
  return probe_contact(body, state.displacement, x, Vec3::Constant(rigid_surface_band_cells * h)).penetrates;
}

Real filter_deformation_gradients(SolverState& s, StepContext& c) {
  Particles& ps = s.particles;
  const Real h = c.settings.cell_size;
  Real removed = 0;
  for (size_t body = 0; body < c.body_info.size(); ++body) {
    const BodyInfo& info = c.body_info[body];
    if (info.role != BodyRole::deformable) continue;
    std::vector<size_t> pressing;
    for (size_t k = 0; k < c.rigid_bodies.size(); ++k)
      if (rigid_body_presses(c.rigid_bodies[k], s.diagnostics.rigid[k], k, ps, int32_t(body), h)) pressing.push_back(k);
    std::vector<uint32_t> points;
    for (size_t p = 0; p < ps.size(); ++p) {
      if (size_t(ps.body[p]) != body) continue;
      const bool banded = std::any_of(pressing.begin(), pressing.end(), [&](size_t k) {
        return near_rigid_surface(c.rigid_bodies[k], s.diagnostics.rigid[k], ps.position[p], h);
      });
      if (!banded) points.push_back(uint32_t(p));
    }
    if (points.empty()) continue;
    PointValues values(points.size());  // F⁻¹ = ∂X/∂x, row a the gradient of X_a
    for (size_t n = 0; n < points.size(); ++n) {
      const uint32_t p = points[n];
      const Mat3 inverse = ps.deformation[p].cast<Real>().inverse();
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) values[n][3 * a + b] = inverse(a, b);
      removed += ps.volume0[p] * energy_density(s, c, p);
    }
    std::vector<Vec3> started;  // X_p of the listed points (reference_map)
    if (c.settings.null_space_filter == NullSpaceFilter::reference_map) {
      if (ps.reference_position.size() != ps.size())
        throw NumericalError("null-space filter: the points' reference positions are missing (reference_map)");
      started.reserve(points.size());
      for (uint32_t p : points) started.push_back(ps.reference_position[p]);
    }
    project_onto_grid_gradients(ps, points, c.settings.shape_function, h, values,
                                started.empty() ? nullptr : &started);
    for (size_t n = 0; n < points.size(); ++n) {
      const uint32_t p = points[n];
      Mat3 inverse;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) inverse(a, b) = values[n][3 * a + b];
      const Mat3 f = inverse.inverse();
      const Real j = f.determinant();
      if (!(j > c.settings.min_jacobian) || !f.allFinite()) {
        std::ostringstream msg;
        const Vec3& x = ps.position[p];
        msg << "step " << s.diagnostics.step + 1 << ": the null-space filter gives particle " << ps.id[p]
            << " of body '" << c.bodies[body].name << "' at (" << x[0] << ", " << x[1] << ", " << x[2]
            << ") m J = " << j << " (<= " << c.settings.min_jacobian << "); try a smaller cfl or time step";
        throw NumericalError(msg.str());
      }
      ps.deformation[p] = f.cast<ParticleReal>();
      const Deformation<Real> d = make_deformation(Mat3::Zero(), f, 0);
      Real stress[6];
      for (int k = 0; k < 6; ++k) stress[k] = ps.stress[p][k];
      std::visit([&](const auto& model) {
        // The set-up admits only models whose stress is a function of F (Simulation).
        if constexpr (history_size<std::decay_t<decltype(model)>> == 0)
          update_material_stress(model, d, stress, static_cast<Real*>(nullptr));
      }, info.model);
      for (int k = 0; k < 6; ++k) ps.stress[p][k] = ParticleReal(stress[k]);
      removed -= ps.volume0[p] * energy_density(s, c, p);
    }
  }
  return removed;
}

void null_space_filter_stage(SolverState& s, StepContext& c) {
  const Settings& settings = c.settings;
  if (settings.null_space_filter == NullSpaceFilter::none ||
      (s.diagnostics.step + 1) % settings.null_space_filter_every != 0)
    return;
  // The strain energy the filter removes (or, where the grid-compatible F holds more, puts in)
  // is a numerical change of the transfer's, booked with it.
  const Real removed = filter_deformation_gradients(s, c);
  c.sums.strain -= removed;
  c.sums.transfer_dissipation += removed;
}

}  // namespace latmpm::mpm
