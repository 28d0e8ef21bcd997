// The inversion-free step bound (paper C Eq. 35) against a dense scan of det(F + αD).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "statics/inversion_free_step.hpp"

using namespace latmpm::statics;

TEST_CASE("The step bound is the first α where det(F + αD) falls to ε det F", "[statics]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-1, 1);
  int bounded = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Mat3 F = Mat3::Identity(), D;
    for (int i = 0; i < 9; ++i) F(i / 3, i % 3) += 0.3 * u(rng), D(i / 3, i % 3) = 2 * u(rng);
    if (F.determinant() <= 0.05) continue;
    const Real margin = 0.1, target = margin * F.determinant();
    const Real alpha = inversion_free_step(F, D, margin);
    // Scan: the first α on a fine grid where det drops to the target.
    Real first = std::numeric_limits<Real>::infinity();
    for (int s = 1; s <= 400000; ++s) {
      const Real a = s * 1e-5;
      if ((F + a * D).determinant() <= target) {
        first = a;
        break;
      }
    }
    if (std::isinf(first)) {
      CHECK(alpha > 4);
      continue;
    }
    ++bounded;
    CHECK(alpha == Approx(first).margin(1e-5));
    CHECK((F + alpha * D).determinant() == Approx(target).margin(1e-9));
  }
  CHECK(bounded > 50);
}
