// Every shape function is a partition of unity with consistent gradients and reproduces
// linear fields: Σ S_i = 1, Σ ∇S_i = 0, Σ x_i ⊗ ∇S_i = I — at random points, including
// points on and near cell faces (where linear and GIMP shapes change branch).
#include <catch2/catch.hpp>

#include <random>

#include "mpm/shape_functions.hpp"

using namespace latmpm::mpm;

namespace {
template <class Shape>
struct Sums {
  Real weight = 0;
  Vec3 gradient = Vec3::Zero();
  Mat3 position_gradient = Mat3::Zero();  // Σ x_i ⊗ ∇S_i
  Vec3 position = Vec3::Zero();           // Σ S_i x_i
  Real min_weight = 1;
};

template <class Shape>
Sums<Shape> sums_at(const Vec3& x, const Vec3& half, Real h) {
  constexpr int N = Shape::nodes_per_axis;
  const auto st = make_stencil<Shape>(x, half, 1 / h);
  Sums<Shape> s;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      for (int k = 0; k < N; ++k) {
        const Vec3 xi = h * Vec3(st.base[0] + i, st.base[1] + j, st.base[2] + k);
        const Real w = st.w[i][0] * st.w[j][1] * st.w[k][2];
        const Vec3 g(st.dw[i][0] * st.w[j][1] * st.w[k][2], st.w[i][0] * st.dw[j][1] * st.w[k][2],
                     st.w[i][0] * st.w[j][1] * st.dw[k][2]);
        s.weight += w;
        s.gradient += g;
        s.position_gradient += xi * g.transpose();
        s.position += w * xi;
        s.min_weight = std::min(s.min_weight, w);
      }
  return s;
}

// Random points: half of them snapped onto or within 1e-12 h of a cell face per axis.
std::vector<Vec3> sample_points(Real h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-20, 20);
  std::uniform_int_distribution<int> snap(0, 3);
  std::vector<Vec3> xs;
  for (int n = 0; n < 400; ++n) {
    Vec3 x(u(rng), u(rng), u(rng));
    for (int a = 0; a < 3; ++a) {
      const int mode = snap(rng);
      if (mode == 1) x[a] = std::round(x[a]);
      if (mode == 2) x[a] = std::round(x[a]) + 1e-12;
      if (mode == 3) x[a] = std::round(x[a] * 4) / 4;  // GIMP branch points for l = h/4
    }
    xs.push_back(h * x);
  }
  return xs;
}
}  // namespace

TEMPLATE_TEST_CASE("Shape functions form a partition of unity with linear reproduction", "[mpm][shape]",
                   LinearShape, UgimpShape, CpgimpShape, Bspline2Shape, Bspline3Shape) {
  const Real h = GENERATE(1e-3, 0.64e-3, 1.0);
  // Half-sizes for GIMP: ppc 2 (h/4), ppc 1 (h/2), and for cpGIMP a stretched domain (0.8 h).
  const Real half_cells = GENERATE(0.25, 0.5, 0.8);
  if (half_cells > 0.5 && !std::is_same_v<TestType, CpgimpShape>) return;
  const Vec3 half = Vec3::Constant(half_cells * h);
  for (const Vec3& x : sample_points(h, 17)) {
    const auto s = sums_at<TestType>(x, half, h);
    INFO("x/h = " << (x / h).transpose() << ", half = " << half_cells << " h");
    CHECK(s.weight == Approx(1).margin(1e-13));
    CHECK(s.min_weight >= -1e-15);
    CHECK(s.gradient.norm() * h < 1e-12);
    CHECK((s.position_gradient - Mat3::Identity()).norm() < 1e-11);
    CHECK((s.position - x).norm() / h < 1e-11);
  }
}

TEMPLATE_TEST_CASE("GIMP weights match the piecewise formula of Bardenhagen and Kober", "[mpm][shape]",
                   UgimpShape, CpgimpShape) {
  // S(ξ) for a node at 0, particle at ξ (cell units), half-length l (Paper A Sec. 2).
  auto reference = [](Real xi, Real l) {
    const Real r = std::abs(xi);
    if (r < l) return 1 - (xi * xi + l * l) / (2 * l);
    if (r < 1 - l) return 1 - r;
    if (r < 1 + l) return (1 + l - r) * (1 + l - r) / (4 * l);
    return Real(0);
  };
  const Real l = GENERATE(0.1, 0.25, 0.5);
  for (Real x = -3; x < 3; x += 0.0137) {
    int base;
    Real w[TestType::nodes_per_axis], dw[TestType::nodes_per_axis];
    TestType::weights(x, l, base, w, dw);
    for (int k = 0; k < TestType::nodes_per_axis; ++k) {
      INFO("x = " << x << ", node " << base + k);
      CHECK(w[k] == Approx(reference(x - (base + k), l)).margin(1e-14));
      const Real eps = 1e-7;
      const Real fd = (reference(x + eps - (base + k), l) - reference(x - eps - (base + k), l)) / (2 * eps);
      CHECK(dw[k] == Approx(fd).margin(1e-6));
    }
  }
}

TEST_CASE("Every shape function kind has a name that parses back", "[mpm][shape]") {
  for (auto kind : {ShapeFunctionKind::linear, ShapeFunctionKind::ugimp, ShapeFunctionKind::cpgimp,
                    ShapeFunctionKind::bspline2, ShapeFunctionKind::bspline3, ShapeFunctionKind::ddmp})
    CHECK(parse_shape_function(to_string(kind)) == kind);
  CHECK_THROWS_WITH(parse_shape_function("gimp", "scene.toml", "solver.shape_function"),
                    Catch::Contains("scene.toml") && Catch::Contains("ugimp"));
}

TEMPLATE_TEST_CASE("GIMP weights stay accurate at the edge of their support", "[mpm][shape]", UgimpShape,
                   CpgimpShape) {
  // Points on the voxelizer's lattice put the particle-domain edge exactly on a node. A
  // weight computed as the difference of two numbers near 1 is pure round-off there, and a
  // node with a round-off mass and an exact force accelerates without bound (the blow-up
  // this test guards against). Near the edge S = d²/(4 l h) and dS/dx = d/(2 l h) for a
  // distance d inside the support.
  const Real l = 0.25;
  for (Real d : {1e-3, 1e-6, 1e-9}) {
    const Real x = 2 + 1 + l - d;  // node 2's support ends at 2 + 1 + l: distance d inside
    const Real inside = (2 + 1 + l) - x;  // d as represented (exact: Sterbenz)
    int base;
    Real w[TestType::nodes_per_axis], dw[TestType::nodes_per_axis];
    TestType::weights(x, l, base, w, dw);
    const int k = 2 - base;
    REQUIRE(k >= 0);
    REQUIRE(k < TestType::nodes_per_axis);
    INFO("d = " << d);
    CHECK(w[k] == Approx(inside * inside / (4 * l)).epsilon(1e-12));
    CHECK(dw[k] == Approx(-inside / (2 * l)).epsilon(1e-12));
  }
}
