// MMA steps through NLopt (mma_step.hpp) on a problem with a known optimum:
//   min Σ c_i / x_i  s.t.  Σ x_i ≤ 1, 0.01 ≤ x_i ≤ 1
// whose KKT point is x_i = √c_i / Σ √c_j. Repeated single steps, each starting NLopt afresh
// with move limits as the optimisation loop does, reach it.
#include <catch2/catch.hpp>

#include <cmath>

#include "optimize/mma_step.hpp"

using namespace latmpm::optimize;

TEST_CASE("Repeated MMA steps reach the optimum of a separable problem with a volume bound", "[optimize]") {
  const std::vector<double> c{1, 4, 9, 16};
  const size_t n = c.size();
  MmaInput in;
  in.x.assign(n, 0.25);
  in.lower.assign(n, 0.01);
  in.upper.assign(n, 1);
  in.move.assign(n, 0.2);
  for (int k = 0; k < 60; ++k) {
    in.objective = 0;
    in.objective_gradient.resize(n);
    in.constraint = -1;
    in.constraint_gradient.assign(n, 1);
    for (size_t i = 0; i < n; ++i) {
      in.objective += c[i] / in.x[i];
      in.objective_gradient[i] = -c[i] / (in.x[i] * in.x[i]);
      in.constraint += in.x[i];
    }
    const std::vector<double> next = mma_step(in);
    for (size_t i = 0; i < n; ++i) CHECK(std::abs(next[i] - in.x[i]) <= 0.2 + 1e-12);
    in.x = next;
  }
  double total = 0;
  for (double v : c) total += std::sqrt(v);
  for (size_t i = 0; i < n; ++i) CHECK(in.x[i] == Approx(std::sqrt(c[i]) / total).epsilon(1e-3));
}
