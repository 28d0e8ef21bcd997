// CPDI1 (paper B Eq. 7) over trilinear hexahedral domains: exact domain integrals, partition
// of unity and linear completeness for distorted domains, the convected update of the
// vertices, and a patch test on a conforming distorted mesh (uniform stress gives no force at
// nodes away from the boundary; a linear velocity field is reproduced with its gradient).
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <map>
#include <random>

#include "core/errors.hpp"
#include "mpm/cpdi.hpp"

using namespace latmpm;
using namespace latmpm::mpm;

namespace {

HexVertices box(const Vec3& lo, const Vec3& size) {
  HexVertices x;
  for (int a = 0; a < 8; ++a)
    x[a] = lo + size.cwiseProduct((hex_reference_vertex(a) + Vec3::Ones()) / 2);
  return x;
}

// A brick with non-planar faces: a box's vertices moved at random, then mapped by a random F.
HexVertices distorted(std::mt19937& rng, Real h) {
  std::uniform_real_distribution<Real> u(-1, 1);
  HexVertices x = box(Vec3(u(rng), u(rng), u(rng)) * 3 * h, Vec3(0.6, 0.9, 1.3) * h);
  for (auto& v : x) v += 0.12 * h * Vec3(u(rng), u(rng), u(rng));
  Mat3 F = Eigen::AngleAxis<Real>(3 * u(rng), Vec3(u(rng), u(rng), 1).normalized()).toRotationMatrix();
  for (int i = 0; i < 9; ++i) F(i) += 0.2 * u(rng);
  REQUIRE(F.determinant() > 0.3);
  for (auto& v : x) v = F * v;
  return x;
}

// Reference for the exact integrals: 5×5×5 Gauss–Legendre points (a different rule).
HexIntegrals fine_quadrature(const HexVertices& x) {
  const Real g[5] = {-0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640};
  const Real w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891};
  HexIntegrals out;
  for (auto& v : out.vertex_gradient) v.setZero();
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k) {
        const Vec3 xi(g[i], g[j], g[k]);
        Real q[8];
        Vec3 dq[8];
        Mat3 J = Mat3::Zero();
        for (int a = 0; a < 8; ++a) {
          const Vec3 s = hex_reference_vertex(a);
          const Vec3 f = Vec3::Ones() + s.cwiseProduct(xi);
          q[a] = f.prod() / 8;
          dq[a] = Vec3(s.x() * f.y() * f.z(), f.x() * s.y() * f.z(), f.x() * f.y() * s.z()) / 8;
          J += x[a] * dq[a].transpose();
        }
        const Real dv = w[i] * w[j] * w[k] * J.determinant();
        out.volume += dv;
        for (int a = 0; a < 8; ++a) {
          out.vertex_weight[a] += q[a] * dv;
          out.vertex_gradient[a] += J.inverse().transpose() * dq[a] * dv;
        }
      }
  return out;
}

}  // namespace

TEST_CASE("Hexahedron integrals are exact for distorted trilinear bricks", "[mpm][cpdi]") {
  const HexIntegrals cube = hex_integrals(box(Vec3(1, 2, 3), Vec3(2, 3, 4)));
  CHECK(cube.volume == Approx(24).epsilon(1e-14));
  for (Real w : cube.vertex_weight) CHECK(w == Approx(3).epsilon(1e-14));
  CHECK((cube.centroid - Vec3(2, 3.5, 5)).norm() <= 1e-14);
  std::mt19937 rng(11);
  for (int n = 0; n < 50; ++n) {
    const HexVertices x = distorted(rng, 1);
    const HexIntegrals exact = hex_integrals(x), ref = fine_quadrature(x);
    REQUIRE(exact.min_jacobian > 0);
    CHECK(exact.volume == Approx(ref.volume).epsilon(1e-13));
    Vec3 gradient_sum = Vec3::Zero();
    for (int a = 0; a < 8; ++a) {
      CHECK(exact.vertex_weight[a] == Approx(ref.vertex_weight[a]).epsilon(1e-12));
      CHECK((exact.vertex_gradient[a] - ref.vertex_gradient[a]).norm() <= 1e-12 * ref.vertex_gradient[a].norm());
      gradient_sum += exact.vertex_gradient[a];
    }
    CHECK(gradient_sum.norm() <= 1e-14);
  }
}

TEST_CASE("CPDI1 functions are a partition of unity and linearly complete on distorted domains", "[mpm][cpdi]") {
  std::mt19937 rng(5);
  const Real h = 0.4e-3;
  for (int n = 0; n < 200; ++n) {
    const HexVertices x = distorted(rng, h);
    const CpdiStencil s = cpdi_stencil(x, h);
    const Vec3 centroid = hex_integrals(x).centroid;
    Real sum = 0;
    Vec3 first_moment = Vec3::Zero(), gradient_sum = Vec3::Zero();
    Mat3 gradient_moment = Mat3::Zero();
    for (size_t e = 0; e < s.size(); ++e) {
      const Vec3 xi = s.node(e).cast<Real>() * h;
      sum += s.weight[e];
      first_moment += s.weight[e] * xi;
      gradient_sum += s.gradient[e];
      gradient_moment += xi * s.gradient[e].transpose();
    }
    CHECK(sum == Approx(1).epsilon(1e-13));
    CHECK((first_moment - centroid).norm() <= 1e-12 * h);
    CHECK(gradient_sum.norm() <= 1e-12 / h);
    CHECK((gradient_moment - Mat3::Identity()).norm() <= 1e-12);
  }
}

TEST_CASE("CPDI1 vertices convect with F: volume J v0 and the centroid moves with the particle", "[mpm][cpdi]") {
  std::mt19937 rng(2);
  const HexVertices X = distorted(rng, 1);
  const HexIntegrals ref = hex_integrals(X);
  HexVertices offsets;
  for (int a = 0; a < 8; ++a) offsets[a] = X[a] - ref.centroid;
  Mat3 F;
  F << 1.3, 0.4, 0.1, -0.2, 0.8, 0.3, 0.05, 0.1, 1.1;
  const Vec3 xp(4, 5, 6);
  const HexIntegrals now = hex_integrals(convected_vertices(xp, F, offsets));
  CHECK(now.volume == Approx(F.determinant() * ref.volume).epsilon(1e-13));
  CHECK((now.centroid - xp).norm() <= 1e-13);
  const Mat3 push = F.determinant() * F.inverse().transpose();
  for (int a = 0; a < 8; ++a) CHECK((now.vertex_gradient[a] - push * ref.vertex_gradient[a]).norm() <= 1e-12);
}

TEST_CASE("The convected CPDI1 stencil from reference integrals equals the one from current vertices", "[mpm][cpdi]") {
  std::mt19937 rng(4);
  std::uniform_real_distribution<Real> u(-1, 1);
  const Real h = 0.4e-3;
  for (int n = 0; n < 50; ++n) {
    const HexVertices X = distorted(rng, h);
    const CpdiDomain domain = make_cpdi_domain(X);
    Mat3 F = Eigen::AngleAxis<Real>(3 * u(rng), Vec3(u(rng), 1, u(rng)).normalized()).toRotationMatrix();
    for (int i = 0; i < 9; ++i) F(i) += 0.3 * u(rng);
    if (!(F.determinant() > 0.2)) continue;
    const Vec3 xp = 2 * h * Vec3(u(rng), u(rng), u(rng));
    const CpdiStencil fast = cpdi_stencil(domain, xp, F, h);
    const CpdiStencil direct = cpdi_stencil(convected_vertices(xp, F, domain.offsets), h);
    REQUIRE(fast.first_node == direct.first_node);
    REQUIRE(fast.node_count == direct.node_count);
    CHECK(fast.volume == Approx(direct.volume).epsilon(1e-13));
    for (size_t e = 0; e < fast.size(); ++e) {
      CHECK(fast.weight[e] == Approx(direct.weight[e]).margin(1e-14));
      CHECK((fast.gradient[e] - direct.gradient[e]).norm() <= 1e-12 / h);
    }
  }
}

TEST_CASE("CPDI1 passes the patch test on a conforming distorted hexahedral mesh", "[mpm][cpdi]") {
  // 12³ bricks of 0.5 m on [0.25, 6.25]³ m, interior vertices moved up to 0.1 m; grid h = 1 m.
  const int n = 12;
  const Real h = 1, a = 0.5;
  std::mt19937 rng(9);
  std::uniform_real_distribution<Real> u(-0.1, 0.1);
  std::vector<Vec3> vertex((n + 1) * (n + 1) * (n + 1));
  auto id = [&](int i, int j, int k) { return size_t(i + (n + 1) * (j + (n + 1) * k)); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        Vec3 v = Vec3(0.25, 0.25, 0.25) + a * Vec3(i, j, k);
        const bool interior = i > 0 && j > 0 && k > 0 && i < n && j < n && k < n;
        if (interior) v += Vec3(u(rng), u(rng), u(rng));
        vertex[id(i, j, k)] = v;
      }
  Mat3 sigma;
  sigma << 3, 1, -2, 1, -4, 0.5, -2, 0.5, 2;
  Mat3 A;
  A << 0.3, -1, 0.2, 0.7, 0.1, -0.4, 0.05, 0.9, -0.6;
  const Vec3 b(1, -2, 0.5);
  std::map<std::tuple<int, int, int>, Vec3> force;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        HexVertices x;
        for (int c = 0; c < 8; ++c) {
          const Vec3 r = (hex_reference_vertex(c) + Vec3::Ones()) / 2;
          x[c] = vertex[id(i + int(r.x()), j + int(r.y()), k + int(r.z()))];
        }
        const CpdiStencil s = cpdi_stencil(x, h);
        const Vec3 xp = hex_integrals(x).centroid;
        Vec3 v = Vec3::Zero();
        Mat3 L = Mat3::Zero();
        for (size_t e = 0; e < s.size(); ++e) {
          const Eigen::Vector3i I = s.node(e);
          const Vec3 vi = A * I.cast<Real>() * h + b;
          v += s.weight[e] * vi;
          L += vi * s.gradient[e].transpose();
          force.try_emplace({I.x(), I.y(), I.z()}, Vec3::Zero()).first->second -= s.volume * sigma * s.gradient[e];  // f_I = −Σ v σ ∇S_I
        }
        CHECK((v - (A * xp + b)).norm() <= 1e-12);
        CHECK((L - A).norm() <= 1e-12);
      }
  Vec3 total = Vec3::Zero();
  int interior_nodes = 0;
  for (const auto& [I, f] : force) {
    total += f;
    // Nodes whose tent support holds no boundary vertex: supports inside (0.25, 6.25)³.
    const bool inside = std::get<0>(I) >= 2 && std::get<0>(I) <= 5 && std::get<1>(I) >= 2 &&
                        std::get<1>(I) <= 5 && std::get<2>(I) >= 2 && std::get<2>(I) <= 5;
    if (inside) {
      ++interior_nodes;
      CHECK(f.norm() <= 1e-12 * sigma.norm() * h * h);
    }
  }
  CHECK(interior_nodes == 64);
  CHECK(total.norm() <= 1e-11 * sigma.norm());
}

TEST_CASE("An inverted CPDI domain is refused", "[mpm][cpdi]") {
  HexVertices x = box(Vec3::Zero(), Vec3::Ones());
  std::swap(x[0], x[6]);
  CHECK_THROWS_AS(cpdi_stencil(x, 1), latmpm::NumericalError);
}
