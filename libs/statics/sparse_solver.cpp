#include "statics/sparse_solver.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <array>
#include <utility>

#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "statics/cholmod_direct.hpp"

namespace latmpm::statics {

namespace {
const std::array<std::pair<LinearSolverKind, const char*>, 3> solver_names{{
    {LinearSolverKind::ldlt, "ldlt"}, {LinearSolverKind::cg, "cg"}, {LinearSolverKind::cholmod, "cholmod"}}};
}

std::string to_string(LinearSolverKind kind) {
  for (const auto& [k, n] : solver_names)
    if (k == kind) return n;
  return "?";
}

std::vector<std::string> linear_solver_names() {
  std::vector<std::string> names;
  for (const auto& [k, n] : solver_names) names.emplace_back(n);
  return names;
}

LinearSolverKind parse_linear_solver(const std::string& name, const std::string& where, const std::string& field) {
  for (const auto& [k, n] : solver_names)
    if (name == n) return k;
  throw InputError(where, field, "unknown value '" + name + "' (expected one of: ldlt, cg, cholmod)");
}

struct SparseSolver::Impl {
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<Real>> cg;
  CholmodDirect cholmod;
  bool analysed = false;
  const SparseMatrix* matrix = nullptr;
};

SparseSolver::SparseSolver(LinearSolverKind kind, Real cg_tolerance, int cg_max_iterations)
    : kind_(kind), impl_(std::make_unique<Impl>()) {
  impl_->cg.setTolerance(cg_tolerance);
  impl_->cg.setMaxIterations(cg_max_iterations);
}

SparseSolver::~SparseSolver() = default;

bool SparseSolver::factorize(const SparseMatrix& K) {
  Impl& s = *impl_;
  s.matrix = &K;
  switch (kind_) {
    case LinearSolverKind::ldlt:
      if (!s.analysed) s.ldlt.analyzePattern(K);
      s.analysed = true;
      s.ldlt.factorize(K);
      return s.ldlt.info() == Eigen::Success && s.ldlt.vectorD().minCoeff() > 0;
    case LinearSolverKind::cg:
      s.cg.compute(K);  // the incomplete factorisation is redone for each matrix
      return s.cg.info() == Eigen::Success;
    case LinearSolverKind::cholmod:
      if (!s.cholmod.analysed()) s.cholmod.analyse(K);
      return s.cholmod.factorize(K);
  }
  return false;
}

std::string SparseSolver::describe() const {
  if (kind_ != LinearSolverKind::cholmod || !impl_->cholmod.analysed()) return to_string(kind_);
  const CholmodFigures& f = impl_->cholmod.figures();
  return "cholmod (supernodal, " + f.ordering + " ordering of the " + (f.node_ordering ? "node" : "unknown") +
         " graph, nnz(L) " + format_number("%.3g", f.factor_nonzeros) + ", " + format_number("%.3g", f.flops) +
         " flops per factorisation)";
}

Vector SparseSolver::solve(const Vector& b, LinearSolveStats& stats) {
  Impl& s = *impl_;
  Vector x;
  stats.iterations = 1;
  switch (kind_) {
    case LinearSolverKind::ldlt: x = s.ldlt.solve(b); break;
    case LinearSolverKind::cholmod: x = s.cholmod.solve(b); break;
    case LinearSolverKind::cg:
      x = s.cg.solve(b);
      stats.iterations = int(s.cg.iterations());
      if (s.cg.info() != Eigen::Success)
        throw NumericalError("static solve: conjugate gradients did not converge in " +
                             std::to_string(s.cg.iterations()) + " iterations (relative residual " +
                             std::to_string(s.cg.error()) + ")");
      break;
  }
  const Real norm_b = b.norm();
  stats.relative_residual = norm_b > 0 ? (*s.matrix * x - b).norm() / norm_b : Real(0);
  return x;
}

}  // namespace latmpm::statics
