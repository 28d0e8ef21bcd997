#include <catch2/catch.hpp>

#include <cmath>

#include "post/curve.hpp"

using namespace latmpm::post;

namespace {

Curve sampled(double (*f)(double), double x0, double x1, size_t intervals) {
  Curve c;
  for (size_t i = 0; i <= intervals; ++i) {
    const double x = x0 + (x1 - x0) * double(i) / double(intervals);
    c.x.push_back(x), c.y.push_back(f(x));
  }
  return c;
}

}  // namespace

TEST_CASE("The trapezoid rule has its known error on a parabola", "[post]") {
  // ∫₀¹ x² dx = 1/3; the composite trapezoid rule with n intervals overestimates by 1/(6n²).
  const size_t n = GENERATE(1, 2, 7, 100);
  const Curve c = sampled([](double x) { return x * x; }, 0, 1, n);
  CHECK(trapezoid(c) == Approx(1.0 / 3 + 1.0 / (6.0 * double(n * n))).epsilon(1e-12));
  CHECK(cumulative_trapezoid(c).back() == Approx(trapezoid(c)).epsilon(1e-14));
}

TEST_CASE("The trapezoid integral of a sine converges to the exact work", "[post]") {
  // ∫₀^π sin x dx = 2; error bound (π³/12n²) max|f''|.
  const Curve c = sampled([](double x) { return std::sin(x); }, 0, M_PI, 400);
  CHECK(std::abs(trapezoid(c) - 2.0) <= std::pow(M_PI, 3) / (12.0 * 400 * 400));
  // Running backwards subtracts: unloading returns work.
  Curve back{{0, 1, 2, 1, 0}, {1, 1, 1, 1, 1}};
  CHECK(trapezoid(back) == Approx(0).margin(1e-15));
}

TEST_CASE("The least-squares slope recovers a line inside its range only", "[post]") {
  Curve c;
  for (int i = 0; i <= 100; ++i) {
    const double x = 0.01 * i;
    c.x.push_back(x);
    c.y.push_back(x <= 0.5 ? 3 * x + 2 : 3.5 - 10 * (x - 0.5));  // a knee at 0.5
  }
  CHECK(fitted_slope(c, 0, 0.5) == Approx(3).epsilon(1e-12));
  CHECK(fitted_slope(c, 0.5, 1) == Approx(-10).epsilon(1e-12));
  CHECK(std::isnan(fitted_slope(c, 0.501, 0.509)));  // no sample inside
}

TEST_CASE("The interval mean of a line is its value at the midpoint, however it is sampled", "[post]") {
  const Curve c{{0, 0.1, 0.15, 0.7, 1.0}, {1, 1.2, 1.3, 2.4, 3.0}};  // y = 1 + 2x, uneven samples
  const double a = GENERATE(0.0, 0.05, 0.12), b = GENERATE(0.3, 0.99);
  CHECK(interval_mean(c, a, b) == Approx(1 + (a + b)).epsilon(1e-12));
}

TEST_CASE("Bin averages remove an alternating oscillation and keep the trend", "[post]") {
  Curve c;
  for (int i = 0; i < 1000; ++i) {
    const double x = (i + 0.5) / 1000.0;
    c.x.push_back(x);
    c.y.push_back(2 * x + (i % 2 ? 0.3 : -0.3));
  }
  const Curve b = bin_average(c, 0, 1, 0.01);  // ten samples per bin, five of each sign
  REQUIRE(b.size() == 100);
  for (size_t k = 0; k < b.size(); ++k) {
    CHECK(b.x[k] == Approx(0.01 * (k + 0.5)).epsilon(1e-12));
    CHECK(b.y[k] == Approx(2 * b.x[k]).epsilon(1e-9));
  }
}

TEST_CASE("Interpolation is linear between samples and clamps outside", "[post]") {
  const Curve c{{0, 1, 3}, {0, 10, 30}};
  CHECK(interpolate(c, 0.25) == Approx(2.5));
  CHECK(interpolate(c, 2) == Approx(20));
  CHECK(interpolate(c, -1) == 0);
  CHECK(interpolate(c, 9) == 30);
}

TEST_CASE("The monotone prefix stops where the travel goes back", "[post]") {
  const Curve c{{0, 1, 2, 2, 1.5, 3}, {0, 1, 2, 3, 4, 5}};
  const Curve m = monotone_prefix(c);
  CHECK(m.x == std::vector<double>{0, 1, 2, 2});
  CHECK(m.y == std::vector<double>{0, 1, 2, 3});
}
