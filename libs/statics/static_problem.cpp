#include "statics/static_problem.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "statics/affine_stabilisation.hpp"
#include "statics/spd_projection.hpp"

namespace latmpm::statics {

namespace {
constexpr size_t chunk = 1024;  // fixed chunks: sums in a fixed order for any thread count
}

StaticProblem::StaticProblem(NarrowBand band, std::vector<Real> volume, std::vector<uint16_t> material,
                             std::vector<ElasticEnergy> energies)
    : band_(std::move(band)), volume_(std::move(volume)), material_(std::move(material)),
      energies_(std::move(energies)), external_(Vector::Zero(Eigen::Index(3 * band_.node_count()))),
      matrix_(band_) {}

template <class F>
void StaticProblem::for_points(F&& f) const {
  const size_t n = point_count();
  tbb::parallel_for(size_t(0), (n + chunk - 1) / chunk, [&](size_t c) {
    const size_t end = std::min(n, (c + 1) * chunk);
    for (size_t p = c * chunk; p < end; ++p) f(c, p);
  });
}

void StaticProblem::set_point_forces(const std::vector<Vec3>& force) {
  external_.setZero();
  for (size_t p = 0; p < point_count(); ++p)
    for (uint32_t e = band_.point_offset[p]; e < band_.point_offset[p + 1]; ++e)
      external_.segment<3>(3 * band_.entry_node[e]) += band_.entry_weight[e] * force[p];
}

void StaticProblem::set_stabilisation(Real beta) {
  stabilisation_ = beta;
  stabilisation_blocks_.clear();
  if (beta == 0) return;
  const Real h = band_.cell_size;
  std::vector<Real> coefficient(point_count());
  for (size_t p = 0; p < point_count(); ++p) coefficient[p] = beta * energies_[material_[p]].mu * volume_[p] / (h * h);
  stabilisation_blocks_ = affine_stabilisation_blocks(matrix_, band_, coefficient);
}

Mat3 StaticProblem::deformation_gradient(size_t p, const Vector& u) const {
  Mat3 F = Mat3::Identity();
  for (uint32_t e = band_.point_offset[p]; e < band_.point_offset[p + 1]; ++e)
    F += u.segment<3>(3 * band_.entry_node[e]) * band_.entry_gradient[e].transpose();
  return F;
}

std::vector<Mat3> StaticProblem::deformation_gradients(const Vector& u) const {
  std::vector<Mat3> F(point_count());
  for_points([&](size_t, size_t p) { F[p] = deformation_gradient(p, u); });
  return F;
}

Real StaticProblem::min_jacobian(const Vector& u) const {
  std::vector<Real> low((point_count() + chunk - 1) / chunk, std::numeric_limits<Real>::infinity());
  for_points([&](size_t c, size_t p) { low[c] = std::min(low[c], deformation_gradient(p, u).determinant()); });
  return low.empty() ? Real(1) : *std::min_element(low.begin(), low.end());
}

Real StaticProblem::energy(const Vector& u) const {
  std::vector<Real> part((point_count() + chunk - 1) / chunk, Real(0));
  for_points([&](size_t c, size_t p) {
    part[c] += volume_[p] * energies_[material_[p]].density(deformation_gradient(p, u));
  });
  Real sum = 0;
  for (Real s : part) sum += s;
  if (!stabilisation_blocks_.empty()) {
    Vector Ku = Vector::Zero(u.size());
    matrix_.multiply_blocks(stabilisation_blocks_, u, Ku);
    sum += Real(0.5) * u.dot(Ku);
  }
  return sum - external_.dot(u);
}

Vector StaticProblem::internal_force(const Vector& u) const {
  std::vector<Mat3> stress(point_count());  // V_p P_p
  for_points([&](size_t, size_t p) {
    stress[p] = volume_[p] * energies_[material_[p]].first_piola(deformation_gradient(p, u));
  });
  Vector f(static_cast<Eigen::Index>(dof_count()));
  tbb::parallel_for(tbb::blocked_range<size_t>(0, band_.node_count(), 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t n = r.begin(); n < r.end(); ++n) {
      Vec3 sum = Vec3::Zero();
      for (uint32_t k = band_.node_entry_offset[n]; k < band_.node_entry_offset[n + 1]; ++k) {
        const uint32_t e = band_.node_entry[k];
        sum += stress[band_.entry_point[e]] * band_.entry_gradient[e];  // f_i,a = V P_ab ∇S_i,b
      }
      f.segment<3>(Eigen::Index(3 * n)) = sum;
    }
  });
  if (!stabilisation_blocks_.empty()) matrix_.multiply_blocks(stabilisation_blocks_, u, f);
  return f;
}

bool StaticProblem::is_quadratic() const {
  return std::all_of(energies_.begin(), energies_.end(), [](const ElasticEnergy& e) { return e.is_quadratic(); });
}

void StaticProblem::assemble_hessian(const Vector& u, bool projected) {
  PhaseTimer timer(assembly_time_);
  if (is_quadratic()) {  // constant tangents, positive semidefinite for λ, μ ≥ 0
    std::vector<Mat9> tangent(energies_.size());
    for (size_t m = 0; m < energies_.size(); ++m) tangent[m] = energies_[m].tangent(Mat3::Identity());
    matrix_.assemble([&](size_t p, Mat9& A) { A = volume_[p] * tangent[material_[p]]; });
    if (!stabilisation_blocks_.empty()) matrix_.add_blocks(stabilisation_blocks_);
    return;
  }
  point_tangent_.resize(point_count());
  for_points([&](size_t, size_t p) {
    const Mat9 A = energies_[material_[p]].tangent(deformation_gradient(p, u));
    point_tangent_[p] = volume_[p] * (projected ? project_to_semidefinite(A) : A);
  });
  matrix_.assemble([&](size_t p, Mat9& A) { A = point_tangent_[p]; });
  if (!stabilisation_blocks_.empty()) matrix_.add_blocks(stabilisation_blocks_);
}

}  // namespace latmpm::statics
