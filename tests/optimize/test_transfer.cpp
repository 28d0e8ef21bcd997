// The carrier-to-quadrature transfer of paper C Sec. 3.1: the cubic spline kernel is
// normalised (∫W = 1, Eq. 8), carriers on the quadrature lattice reproduce a uniform density
// (partition of unity: the initial volume fraction), and the smooth clamp is the identity
// below its knee, one above its end, with a continuous slope (Eq. 11-12).
#include <catch2/catch.hpp>

#include "optimize/carrier_transfer.hpp"
#include "optimize/optimisation.hpp"
#include "small_cantilever.hpp"

using namespace latmpm::optimize;

TEST_CASE("The cubic spline kernel integrates to one in 2D and 3D", "[optimize]") {
  for (int d : {2, 3}) {
    const CubicSplineKernel W{1.0, d};
    // Midpoint rule over [-1, 1]^d.
    const int n = d == 2 ? 400 : 100;
    const double s = 2.0 / n;
    double sum = 0;
    for (int k = 0; k < (d == 3 ? n : 1); ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const double x = -1 + (i + 0.5) * s, y = -1 + (j + 0.5) * s, z = d == 3 ? -1 + (k + 0.5) * s : 0;
          sum += W.value(std::sqrt(x * x + y * y + z * z)) * std::pow(s, d);
        }
    CAPTURE(d);
    CHECK(sum == Approx(1).epsilon(2e-3));
    // dW/dr against a central difference.
    for (double r : {0.2, 0.5, 0.7, 0.95})
      CHECK(W.derivative(r) == Approx((W.value(r + 1e-6) - W.value(r - 1e-6)) / 2e-6).epsilon(1e-6));
  }
}

TEST_CASE("Carriers on the quadrature points give every interior point the volume fraction", "[optimize]") {
  for (bool planar : {true, false}) {
    const DesignGrid g = test::small_grid(planar);
    CarrierTransfer transfer(g, 1.5 * g.cell_size, SmoothClamp{0.9});
    std::vector<double> sum, rho;
    transfer.densities(carriers_on_quadrature(g, 0.3), sum, rho);
    // Interior: the kernel support lies inside the domain.
    for (size_t q = 0; q < g.point_count(); ++q) {
      const Vec3 x = g.position(q), e = g.extent();
      bool interior = true;
      for (int a = 0; a < g.dimension(); ++a) interior = interior && x[a] > 1.5e-3 && x[a] < e[a] - 1.5e-3;
      if (interior) CHECK(rho[q] == Approx(0.3).epsilon(0.02));
    }
  }
}

TEST_CASE("The smooth clamp is the identity below its knee and one above its end, with a continuous slope", "[optimize]") {
  const SmoothClamp c{0.9};
  CHECK(c.value(0.5) == 0.5);
  CHECK(c.value(0.9) == Approx(0.9));
  CHECK(c.value(1.1) == Approx(1));
  CHECK(c.value(3.0) == 1);
  CHECK(c.derivative(3.0) == 0);
  for (double x : {0.85, 0.95, 1.0, 1.05, 1.15})
    CHECK(c.derivative(x) == Approx((c.value(x + 1e-7) - c.value(x - 1e-7)) / 2e-7).margin(1e-6));
  // Monotone and at most one.
  for (double x = 0; x < 2; x += 0.01) CHECK(c.value(x + 0.01) >= c.value(x));
}
