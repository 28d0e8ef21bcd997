// The energies' stress and tangent against independent references: the explicit solver's
// neo-Hookean stress (libs/mpm) and central finite differences of ψ and P.
#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>

#include "mpm/neo_hookean.hpp"
#include "mpm/material_model.hpp"
#include "statics/elastic_energy.hpp"
#include "statics/spd_projection.hpp"

using namespace latmpm;
using namespace latmpm::statics;

namespace {
mpm::MaterialParameters params(mpm::MaterialKind kind) {
  mpm::MaterialParameters m;
  m.kind = kind;
  m.young_modulus = 10e6;
  m.poisson_ratio = 0.3;
  m.density = 1000;
  return m;
}

Mat3 sample_deformation(int which) {
  Mat3 F;
  if (which == 0) F << 1.1, 0.2, -0.05, 0.03, 0.9, 0.1, -0.1, 0.05, 1.05;
  else F << 0.6, -0.3, 0.1, 0.2, 1.3, 0.0, 0.05, -0.2, 0.8;  // large strain, det > 0
  return F;
}
}  // namespace

TEST_CASE("The neo-Hookean Cauchy stress equals the explicit solver's", "[statics]") {
  const mpm::MaterialParameters m = params(mpm::MaterialKind::neo_hookean);
  const ElasticEnergy energy = ElasticEnergy::from(m);
  const Mat3 F = sample_deformation(GENERATE(0, 1));
  const Mat3 sigma = cauchy_stress(F, energy.first_piola(F));
  const mpm::SymTensor explicit_sigma =
      mpm::updated_stress(mpm::NeoHookean::from(m, 1), Mat3::Zero(), F, 0, mpm::SymTensor::Zero());
  CHECK((mpm::to_voigt(sigma) - explicit_sigma).norm() <= 1e-9 * explicit_sigma.norm());
  CHECK(energy.density(F) == Approx(mpm::strain_energy_density(mpm::NeoHookean::from(m, 1), F, explicit_sigma)).epsilon(1e-12));
}

TEST_CASE("Stress and tangent are the derivatives of the energy (finite differences)", "[statics]") {
  const auto kind = GENERATE(mpm::MaterialKind::linear_elastic, mpm::MaterialKind::neo_hookean);
  const ElasticEnergy energy = ElasticEnergy::from(params(kind));
  const Mat3 F = sample_deformation(GENERATE(0, 1));
  const Real step = 1e-6;
  const Mat3 P = energy.first_piola(F);
  const Mat9 A = energy.tangent(F);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      Mat3 dF = Mat3::Zero();
      dF(a, b) = step;
      const Real dpsi = (energy.density(F + dF) - energy.density(F - dF)) / (2 * step);
      CHECK(dpsi == Approx(P(a, b)).margin(1e-6 * P.norm()));
      const Mat3 dP = (energy.first_piola(F + dF) - energy.first_piola(F - dF)) / (2 * step);
      for (int c = 0; c < 3; ++c)
        for (int d = 0; d < 3; ++d) CHECK(dP(c, d) == Approx(A(3 * c + d, 3 * a + b)).margin(1e-6 * A.norm()));
    }
  CHECK((A - A.transpose()).norm() <= 1e-9 * A.norm());  // hyperelastic: major symmetry
}

TEST_CASE("The projected tangent is semidefinite and unchanged where it already was", "[statics]") {
  const ElasticEnergy energy = ElasticEnergy::from(params(mpm::MaterialKind::neo_hookean));
  const Mat9 A = energy.tangent(sample_deformation(1));  // strongly compressed: indefinite
  Eigen::SelfAdjointEigenSolver<Mat9> before(A);
  REQUIRE(before.eigenvalues().minCoeff() < 0);
  const Mat9 projected = project_to_semidefinite(A);
  Eigen::SelfAdjointEigenSolver<Mat9> after(projected);
  CHECK(after.eigenvalues().minCoeff() >= -1e-9 * A.norm());
  // The positive eigenpairs are kept: the projection is the nearest semidefinite matrix.
  CHECK(after.eigenvalues().maxCoeff() == Approx(before.eigenvalues().maxCoeff()));
  const Mat9 small = energy.tangent(Mat3::Identity());
  CHECK((project_to_semidefinite(small) - small).norm() <= 1e-9 * small.norm());
}
