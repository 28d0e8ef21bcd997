// DDMP's modified gradient (Paper A Eq. 5–8): it satisfies Eq. 8 — Σ_i ∇̄S_i = 0 and
// Σ_i x_i ⊗ ∇̄S_i = I — at random points, on and next to cell faces; its smoothed part
// equals Eq. 7 with V_j and ∫ S_j ∇S_i dV integrated by Gauss quadrature over the grid; the
// partition function α is Eq. 5 as printed, zero on cell faces and positive inside.
// With sub-points the point's gradient is the mean of Eq. 7 at its octant centres.
// (Eq. 8 next to free surfaces, through the solver's passes: test_ddmp_grid.cpp.)
#include <catch2/catch.hpp>

#include <iomanip>
#include <random>
#include <vector>

#include "mpm/settings.hpp"
#include "mpm/shape_ddmp.hpp"
#include "mpm/shape_ddmp_subpoints.hpp"

using namespace latmpm::mpm;

namespace {
struct Sums {
  Real weight = 0;
  Vec3 gradient = Vec3::Zero();
  Mat3 position_gradient = Mat3::Zero();  // Σ x_i ⊗ ∇̄S_i
  Vec3 position = Vec3::Zero();           // Σ S_i x_i
};

Vec3 modified_gradient(const DdmpStencil& st, int i, int j, int k) {
  const Vec3 standard(st.dw[i][0] * st.w[j][1] * st.w[k][2], st.w[i][0] * st.dw[j][1] * st.w[k][2],
                      st.w[i][0] * st.w[j][1] * st.dw[k][2]);
  return standard + st.smoothed[(i * 4 + j) * 4 + k];
}

Sums sums_of(const DdmpStencil& st, Real h) {
  Sums s;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const Vec3 xi = h * Vec3(st.base[0] + i, st.base[1] + j, st.base[2] + k);
        const Real w = st.w[i][0] * st.w[j][1] * st.w[k][2];
        const Vec3 g = modified_gradient(st, i, j, k);
        s.weight += w;
        s.gradient += g;
        s.position_gradient += xi * g.transpose();
        s.position += w * xi;
      }
  return s;
}

}  // namespace

TEST_CASE("DDMP's modified gradient satisfies Eq. 8 at random points and on cell faces", "[mpm][ddmp]") {
  const Real h = GENERATE(1e-3, 0.64e-3, 1.0);
  // Eq. 8 holds for any partition function: Eq. 5 (the default), a study's and α = 1.
  const DdmpPartition alpha = GENERATE(DdmpPartition{}, DdmpPartition{1, 0.125}, DdmpPartition{1, 1e-9});
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> u(-20, 20);
  std::uniform_int_distribution<int> snap(0, 2);
  for (int n = 0; n < 2000; ++n) {
      Vec3 x(u(rng), u(rng), u(rng));
      for (int a = 0; a < 3; ++a) {
        const int mode = snap(rng);
        if (mode == 1) x[a] = std::round(x[a]);  // on a cell face: α = 0
        if (mode == 2) x[a] = std::round(x[a]) + 1e-12;
      }
      x *= h;
      const DdmpStencil st = make_ddmp_stencil(x, 1 / h, alpha);
      const Sums s = sums_of(st, h);
      INFO("x/h = " << (x / h).transpose() << ", h " << h);
      CHECK(s.weight == Approx(1).margin(1e-13));
      CHECK(s.gradient.norm() * h < 1e-12);
      CHECK((s.position_gradient - Mat3::Identity()).norm() < 1e-11);
      CHECK((s.position - x).norm() / h < 1e-11);
    }
}

TEST_CASE("DDMP's smoothed gradient matches Eq. 7 integrated by Gauss quadrature over the grid", "[mpm][ddmp]") {
  // Independent reference: V_j = ∫ S_j dV and ∫ S_j ∇S_i dV by 2-point Gauss quadrature per
  // axis over every cell of the corners' supports (exact: the integrands are quadratic per
  // axis), then Eq. 7 term by term.
  const Real h = 0.64e-3;
  auto tent = [&](Real x, int node) { return std::max(Real(0), 1 - std::abs(x / h - node)); };
  auto tent_slope = [&](Real x, int node) {
    const Real d = x / h - node;
    return std::abs(d) < 1 ? (d < 0 ? 1 / h : -1 / h) : Real(0);
  };
  auto S = [&](const Vec3& x, const int* n) { return tent(x[0], n[0]) * tent(x[1], n[1]) * tent(x[2], n[2]); };
  auto gradS = [&](const Vec3& x, const int* n) {
    return Vec3(tent_slope(x[0], n[0]) * tent(x[1], n[1]) * tent(x[2], n[2]),
                tent(x[0], n[0]) * tent_slope(x[1], n[1]) * tent(x[2], n[2]),
                tent(x[0], n[0]) * tent(x[1], n[1]) * tent_slope(x[2], n[2]));
  };
  const Real g = 0.5 - 0.5 / std::sqrt(3.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(-5, 5);
  for (int n = 0; n < 6; ++n) {
    const Vec3 x = h * Vec3(u(rng), u(rng), u(rng));
    const DdmpStencil st = make_ddmp_stencil(x, 1 / h);
    const int c[3] = {st.base[0] + 1, st.base[1] + 1, st.base[2] + 1};
    // Quadrature points of the 27 cells around the particle's, weight h³/8 each.
    std::vector<Vec3> q;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
          for (int a = 0; a < 8; ++a)
            q.push_back(h * Vec3(c[0] + dx + ((a & 4) ? 1 - g : g), c[1] + dy + ((a & 2) ? 1 - g : g),
                                 c[2] + dz + ((a & 1) ? 1 - g : g)));
    const Real wq = h * h * h / 8;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) {
          const int node_i[3] = {st.base[0] + i, st.base[1] + j, st.base[2] + k};
          Vec3 reference = Vec3::Zero();
          for (int jx = 0; jx < 2; ++jx)
            for (int jy = 0; jy < 2; ++jy)
              for (int jz = 0; jz < 2; ++jz) {
                const int node_j[3] = {c[0] + jx, c[1] + jy, c[2] + jz};
                Real volume = 0;
                Vec3 integral = Vec3::Zero();
                for (const Vec3& y : q) {
                  volume += wq * S(y, node_j);
                  integral += wq * S(y, node_j) * gradS(y, node_i);
                }
                CHECK(volume == Approx(h * h * h).epsilon(1e-13));  // V_j = h³
                reference += S(x, node_j) / volume * integral;
              }
          reference *= 1 - st.alpha;
          INFO("node " << i << j << k);
          CHECK((st.smoothed[(i * 4 + j) * 4 + k] - reference).norm() * h < 1e-12);
        }
  }
}

TEST_CASE("DDMP's partition function vanishes on cell faces and peaks at the centre", "[mpm][ddmp]") {
  const DdmpPartition alpha = GENERATE(DdmpPartition{}, DdmpPartition{0.5, 0.3}, DdmpPartition{1, 0.125});
  CHECK(ddmp_partition(Vec3(0, 0.3, 0.7), alpha) == 0);
  CHECK(ddmp_partition(Vec3(0.2, 1 - 1e-16, 0.5), alpha) < 0.02);
  CHECK(ddmp_partition(Vec3::Constant(0.5), alpha) == Approx(alpha.peak).epsilon(1e-14));
  std::mt19937 rng(1);
  std::uniform_real_distribution<Real> u(1e-6, 1 - 1e-6);
  for (int n = 0; n < 1000; ++n) {
    const Real a = ddmp_partition(Vec3(u(rng), u(rng), u(rng)), alpha);
    CHECK(a > 0);
    CHECK(a <= alpha.peak * (1 + 1e-14));
  }
}

TEST_CASE("DDMP's default partition function is Eq. 5 as printed, continuous across cells", "[mpm][ddmp]") {
  // Independent: ½ {Π_{j=1..8} 2 S_j(x)}^{3/(2 (8 − 1) 3)} over the cell's 8 corners.
  std::mt19937 rng(2);
  std::uniform_real_distribution<Real> u(0, 1);
  for (int n = 0; n < 200; ++n) {
    const Vec3 f(u(rng), u(rng), u(rng));
    Real product = 1;
    for (int j = 0; j < 8; ++j)
      product *= 2 * ((j & 4) ? f[0] : 1 - f[0]) * ((j & 2) ? f[1] : 1 - f[1]) * ((j & 1) ? f[2] : 1 - f[2]);
    CHECK(ddmp_partition(f, DdmpPartition{}) == Approx(0.5 * std::pow(product, 1.0 / 14)).epsilon(1e-12));
  }
  CHECK(DdmpPartition{}.peak == Approx(0.5 * std::pow(2.0, -16.0 / 14.0)).epsilon(1e-14));
  CHECK(Settings{}.ddmp_alpha_peak == DdmpPartition{}.peak);
  CHECK(Settings{}.ddmp_alpha_exponent == DdmpPartition{}.exponent);
  // Continuous across a face: the same value (0) from both cells' sides.
  CHECK(ddmp_partition(Vec3(1 - 1e-15, 0.4, 0.6)) < 1e-4);
  CHECK(ddmp_partition(Vec3(1e-15, 0.4, 0.6)) < 1e-4);
}

TEST_CASE("DDMP's partition function: α of many points at once is the per-point one", "[mpm][ddmp]") {
  // The solver's pass (ddmp_partition_of_points: vectorised log and exp, rounds of 512 points)
  // against ddmp_partition (std::pow) at points anywhere in space, negative coordinates, on
  // cell faces (α = 0) and a count that is not a whole number of rounds.
  const DdmpPartition alpha = GENERATE(DdmpPartition{}, DdmpPartition{1, 0.125});
  const Real h = 1.0 / 1024;  // a power of two: the face and corner points below are exact multiples
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(-40 * h, 40 * h);
  std::vector<Vec3> x(1237);
  for (Vec3& p : x) p = Vec3(u(rng), u(rng), u(rng));
  x[5] = Vec3(3 * h, u(rng), u(rng));      // on a face: α = 0
  x[700] = Vec3(-7 * h, -2 * h, -5 * h);  // on a corner
  std::vector<Real> a(x.size(), -1);
  ddmp_partition_of_points(x.data(), x.size(), 1 / h, alpha, a.data());
  int zeros = 0;
  for (size_t p = 0; p < x.size(); ++p) {
    Vec3 f;
    for (int k = 0; k < 3; ++k) f[k] = x[p][k] * (1 / h) - std::floor(x[p][k] * (1 / h));  // as the solver: x · h⁻¹
    const Real expected = ddmp_partition(f, alpha);
    INFO("point " << p << ": " << std::setprecision(17) << a[p] << " against " << expected);
    CHECK(std::abs(a[p] - expected) <= 1e-13 * alpha.peak);
    zeros += a[p] == 0;
  }
  CHECK(a[5] == 0);
  CHECK(a[700] == 0);
  CHECK(zeros == 2);
}

// DDMP with sub-points (shape_ddmp_subpoints.hpp): the point's α part and corner weights,
// completed with the smoothing stencil G(i − j)/h of the grid pass, equal the mean of the
// per-particle modified gradient (make_ddmp_stencil, Eq. 7 in closed form) at the 8 octant
// centres x_p + F (±l/2), node by node over the 6×6×6 box they reach.
TEST_CASE("DDMP with sub-points averages Eq. 7 over the octant centres of the point's domain", "[mpm][ddmp]") {
  const Real h = 0.4e-3;
  std::mt19937 rng(23);
  std::uniform_real_distribution<Real> u(-1, 1);
  const DdmpPartition alpha{};
  for (int n = 0; n < 200; ++n) {
    const Vec3 x = h * Vec3(10 * u(rng), 10 * u(rng), 10 * u(rng));
    Mat3 F = Mat3::Identity();
    for (int i = 0; i < 9; ++i) F(i) += 0.3 * u(rng);
    const Vec3 half = h / 4 * Vec3(1 + 0.5 * u(rng), 1 + 0.5 * u(rng), 1 + 0.5 * u(rng));
    const DdmpSubpointStencil st = make_ddmp_subpoint_stencil(x, F, half, 1 / h, alpha);
    // The box: nodes base − 1 … base + 4 per axis (the corners' smoothing reaches one more).
    constexpr int W = 6;
    std::vector<Vec3> tested(W * W * W, Vec3::Zero()), reference(W * W * W, Vec3::Zero());
    auto at = [&](std::vector<Vec3>& box, int i, int j, int k) -> Vec3& {
      return box[size_t(((i - st.base[0] + 1) * W + (j - st.base[1] + 1)) * W + (k - st.base[2] + 1))];
    };
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) {
          const int node = (i * 4 + j) * 4 + k;
          at(tested, st.base[0] + i, st.base[1] + j, st.base[2] + k) += st.smoothed[node];
          for (int di = -1; di <= 1; ++di)
            for (int dj = -1; dj <= 1; ++dj)
              for (int dk = -1; dk <= 1; ++dk)  // node i' = j + d gets corner_j G(d) / h
                at(tested, st.base[0] + i + di, st.base[1] + j + dj, st.base[2] + k + dk) +=
                    st.corner[node] / h *
                    Vec3(ddmp_smoothing_slope(di) * ddmp_smoothing_mass(dj) * ddmp_smoothing_mass(dk),
                         ddmp_smoothing_mass(di) * ddmp_smoothing_slope(dj) * ddmp_smoothing_mass(dk),
                         ddmp_smoothing_mass(di) * ddmp_smoothing_mass(dj) * ddmp_smoothing_slope(dk));
        }
    Real largest = 0;
    for (int s = 0; s < 8; ++s) {
      const Vec3 d((s & 4 ? 0.5 : -0.5) * half[0], (s & 2 ? 0.5 : -0.5) * half[1], (s & 1 ? 0.5 : -0.5) * half[2]);
      const DdmpStencil sub = make_ddmp_stencil(x + F * d, 1 / h, alpha);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          for (int k = 0; k < 4; ++k) {
            const Vec3 g = modified_gradient(sub, i, j, k) / 8;
            at(reference, sub.base[0] + i, sub.base[1] + j, sub.base[2] + k) += g;
            largest = std::max(largest, g.norm());
          }
    }
    Real error = 0;
    for (size_t e = 0; e < tested.size(); ++e) error = std::max(error, (tested[e] - reference[e]).norm());
    INFO("x/h = " << (x / h).transpose());
    REQUIRE(largest > 0);
    CHECK(error < 1e-12 * largest);
  }
}
