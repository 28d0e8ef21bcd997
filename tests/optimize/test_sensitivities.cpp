// The adjoint sensitivities of paper C Sec. 3.2 against central finite differences of the
// compliance itself (a static solve per evaluation): the closed form ∂C/∂ρ_q of Eq. (21)
// composed with the carrier transfer (Eq. 9-14) for LETO, and with the filter and
// projection for SIMP; the volume gradient (Eq. 16) the same way. The compliance is also
// checked against ½ fᵀu (Eq. 20: C is the strain energy at equilibrium).
#include <catch2/catch.hpp>

#include <random>

#include "optimize/connectivity.hpp"
#include "optimize/leto_design.hpp"
#include "optimize/optimisation.hpp"
#include "optimize/simp_design.hpp"
#include "small_cantilever.hpp"

using namespace latmpm::optimize;

namespace {

struct Objective {
  const DesignGrid& grid;
  const LoadCase& load_case;
  SimpMaterial material;
  std::vector<char> mask;  // fixed band (Sec. 3.4: constant within an iteration)

  std::vector<double> masked(Parameterisation& design, const std::vector<double>& x) const {
    std::vector<double> rho;
    design.densities(x, rho);
    for (size_t q = 0; q < rho.size(); ++q) rho[q] = mask[q] ? rho[q] : 0;
    return rho;
  }
  double compliance(Parameterisation& design, const std::vector<double>& x) const {
    return evaluate_compliance(grid, masked(design, x), mask, load_case, material).compliance;
  }
  double volume(Parameterisation& design, const std::vector<double>& x) const {
    return volume_fraction(grid, masked(design, x));
  }
};

// Checks `count` components of the adjoint gradient of C and v against central differences.
void check_gradients(Parameterisation& design, const Objective& f, std::vector<double> x,
                     const std::vector<size_t>& components, double step) {
  const std::vector<double> rho = f.masked(design, x);
  const ComplianceResult c = evaluate_compliance(f.grid, rho, f.mask, f.load_case, f.material);
  CHECK(c.compliance == Approx(c.external_work).epsilon(1e-8));
  const std::vector<double> dC = design.pull_back(x, c.gradient);
  std::vector<double> d_volume(rho.size());
  for (size_t q = 0; q < rho.size(); ++q) d_volume[q] = f.mask[q] ? f.grid.point_volume() / f.grid.domain_volume() : 0;
  const std::vector<double> dV = design.pull_back(x, d_volume);
  double scale = 0;
  for (double g : dC) scale = std::max(scale, std::abs(g));
  for (size_t j : components) {
    const double x0 = x[j];
    x[j] = x0 + step;
    const double cp = f.compliance(design, x), vp = f.volume(design, x);
    x[j] = x0 - step;
    const double cm = f.compliance(design, x), vm = f.volume(design, x);
    x[j] = x0;
    const double fd = (cp - cm) / (2 * step), fdv = (vp - vm) / (2 * step);
    CAPTURE(design.name(), j, dC[j], fd, dV[j], fdv);
    CHECK(dC[j] == Approx(fd).epsilon(1e-4).margin(1e-6 * scale));
    CHECK(dV[j] == Approx(fdv).epsilon(1e-4).margin(1e-12));
  }
}

// A random LETO design: carrier densities uniform in [lo, hi], positions jittered by up to
// ±jitter point spacings.
std::vector<double> random_carriers(const LetoDesign& design, const DesignGrid& g, unsigned seed, double lo, double hi,
                                    double jitter) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> density(lo, hi), offset(-jitter, jitter);
  std::vector<double> x = design.initial();
  const size_t n = g.point_count();
  for (size_t c = 0; c < n; ++c) x[c] = density(rng);
  for (size_t j = n; j < x.size(); ++j) x[j] += offset(rng) * g.spacing();
  return x;
}

}  // namespace

TEST_CASE("LETO's adjoint compliance and volume gradients match finite differences", "[optimize]") {
  const bool planar = GENERATE(true, false);
  const DesignGrid g = test::small_grid(planar);
  const LoadCase lc = test::small_load_case(g);
  LetoDesign design(g, LetoSettings{}, 0.5);
  std::vector<double> x = random_carriers(design, g, 7, 0.2, 0.9, 0.4);
  const size_t n = g.point_count();
  std::vector<size_t> components;
  for (size_t k = 0; k < 6; ++k) components.push_back((k * 37 + 5) % n);           // densities
  for (size_t k = 0; k < 6; ++k) components.push_back(n + (k * 53 + 11) % (x.size() - n));  // positions

  SECTION("weak material everywhere (no narrow band)") {
    const Objective f{g, lc, test::small_material(1e-9), std::vector<char>(n, 1)};
    check_gradients(design, f, x, {components.begin(), components.begin() + 6}, 1e-6);
    check_gradients(design, f, x, {components.begin() + 6, components.end()}, 1e-9);
  }
  SECTION("a narrow band: the largest component above ρ = 0.3, no weak material") {
    std::vector<double> rho;
    design.densities(x, rho);
    const auto tip = loaded_points(g, lc)[0];
    const Objective f{g, lc, test::small_material(0), narrow_band_mask(g, rho, 0.3, tip)};
    check_gradients(design, f, x, {components.begin(), components.begin() + 6}, 1e-6);
    check_gradients(design, f, x, {components.begin() + 6, components.end()}, 1e-9);
  }
}

TEST_CASE("LETO's gradients through Eq. 38's sharpening match finite differences", "[optimize]") {
  const DesignGrid g = test::small_grid(true);
  const LoadCase lc = test::small_load_case(g);
  LetoSettings settings;
  settings.sharpen_end = 4;
  LetoDesign design(g, settings, 0.5);
  design.start_iteration(1000);  // β = 4
  CHECK(design.continuation_done());
  const std::vector<double> x = random_carriers(design, g, 5, 0.2, 0.9, 0.4);
  const size_t n = g.point_count();
  const Objective f{g, lc, test::small_material(1e-9), std::vector<char>(n, 1)};
  check_gradients(design, f, x, {3, 17, 40, 77, 101}, 1e-6);
  check_gradients(design, f, x, {n + 5, n + 30, n + 91}, 1e-9);
}

TEST_CASE("Eq. 38's sharpening keeps 0, 1/2 and 1, is flat at both ends and steepens with beta", "[optimize]") {
  for (double beta : {1.01, 2.0, 10.0}) {
    const Sharpening s{beta};
    CHECK(s.value(0) == 0);
    CHECK(s.value(1) == 1);
    CHECK(s.value(0.5) == Approx(0.5));
    CHECK(s.derivative(1e-9) < 1e-6 + (beta < 1.1 ? 2 : 0));
    for (double r : {0.1, 0.3, 0.7}) CHECK(s.derivative(r) == Approx((s.value(r + 1e-6) - s.value(r - 1e-6)) / 2e-6).epsilon(1e-5));
  }
  CHECK(Sharpening{10}.value(0.4) < 0.02);
  CHECK(Sharpening{1.01}.value(0.4) == Approx(0.4).epsilon(0.01));
}

TEST_CASE("SIMP's filtered and projected gradients match finite differences", "[optimize]") {
  const DesignGrid g = test::small_grid(true);
  const LoadCase lc = test::small_load_case(g);
  SimpDesign design(g, SimpSettings{}, 0.5);
  design.start_iteration(50);  // β = 4: a sharp projection
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> density(0.1, 0.9);
  std::vector<double> x = design.initial();
  for (double& v : x) v = density(rng);
  const Objective f{g, lc, test::small_material(1e-9), std::vector<char>(g.point_count(), 1)};
  check_gradients(design, f, x, {0, 5, 9, 14, 20, 27, 31}, 1e-6);
}

TEST_CASE("The neo-Hookean adjoint gradient matches finite differences under a large load", "[optimize]") {
  // Paper C Sec. 3.2-3.3: C is the elastic potential at the nonlinear equilibrium, its
  // gradient the adjoint of Eq. (19) through the static solver's true tangent. The tip load
  // (5 N on the 8 × 4 mm cantilever of random density: about 1 mm of deflection) bends it far enough from linear that C differs from
  // the linear one and from ½ fᵀu (checked).
  const DesignGrid g = test::small_grid(true);
  LoadCase lc = test::small_load_case(g);
  lc.loads[0].force *= 5;
  LetoDesign design(g, LetoSettings{}, 0.5);
  std::vector<double> x = random_carriers(design, g, 11, 0.4, 0.9, 0.3);
  const size_t n = g.point_count();
  std::vector<double> rho;
  design.densities(x, rho);
  SimpMaterial material = test::small_material(0);
  material.model = latmpm::mpm::MaterialKind::neo_hookean;
  const Objective f{g, lc, material, narrow_band_mask(g, rho, 0.3, loaded_points(g, lc)[0])};

  const ComplianceResult c = evaluate_compliance(g, f.masked(design, x), f.mask, lc, material);
  CHECK(c.newton_iterations > 1);
  // Started from a neighbouring design's equilibrium (the optimiser's start for the next
  // design, compliance.hpp): the whole load at once, the same equilibrium and gradient.
  EquilibriumGuess guess;
  std::vector<double> x_near = x;
  for (size_t j = 0; j < n; ++j) x_near[j] *= 1.02;
  evaluate_compliance(g, f.masked(design, x_near), f.mask, lc, material, &guess);
  const ComplianceResult cw = evaluate_compliance(g, f.masked(design, x), f.mask, lc, material, &guess);
  CHECK(cw.from_guess);
  CHECK(cw.newton_iterations < c.newton_iterations);
  CHECK(cw.compliance == Approx(c.compliance).epsilon(1e-9));
  double largest = 0;
  for (double v : c.gradient) largest = std::max(largest, std::abs(v));
  for (size_t q = 0; q < n; ++q) CHECK(cw.gradient[q] == Approx(c.gradient[q]).epsilon(1e-6).margin(1e-9 * largest));
  SimpMaterial linear = material;
  linear.model = latmpm::mpm::MaterialKind::linear_elastic;
  const ComplianceResult cl = evaluate_compliance(g, f.masked(design, x), f.mask, lc, linear);
  // Nonlinear enough: the potential and the gradient differ from the linear ones.
  CAPTURE(c.compliance, cl.compliance, c.external_work);
  CHECK(std::abs(c.compliance / cl.compliance - 1) > 0.01);
  CHECK(std::abs(c.compliance / c.external_work - 1) > 0.01);  // C ≠ ½ fᵀu beyond linear

  std::vector<size_t> density_components, position_components;
  for (size_t k = 0; k < 5; ++k) density_components.push_back((k * 37 + 5) % n);
  for (size_t k = 0; k < 5; ++k) position_components.push_back(n + (k * 53 + 11) % (x.size() - n));
  const std::vector<double> dC = design.pull_back(x, c.gradient);
  double scale = 0;
  for (double v : dC) scale = std::max(scale, std::abs(v));
  // Central difference of the compliance in design component j.
  auto central_difference = [&](size_t j, double step) {
    const double x0 = x[j];
    x[j] = x0 + step;
    const double cp = f.compliance(design, x);
    x[j] = x0 - step;
    const double cm = f.compliance(design, x);
    x[j] = x0;
    return (cp - cm) / (2 * step);
  };
  for (size_t j : density_components) {
    const double fd = central_difference(j, 1e-5);
    CAPTURE(j, dC[j], fd);
    CHECK(dC[j] == Approx(fd).epsilon(1e-4));
  }
  for (size_t j : position_components) {
    const double fd = central_difference(j, 1e-8);
    CAPTURE(j, dC[j], fd);
    CHECK(dC[j] == Approx(fd).epsilon(1e-4).margin(1e-6 * scale));
  }
}
