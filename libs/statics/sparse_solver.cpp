#include "statics/sparse_solver.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <unistd.h>

#include <array>
#include <stdexcept>
#include <utility>

#include "core/errors.hpp"
#include "core/number_text.hpp"
#include "mpm/name_table.hpp"
#include "statics/cholmod_direct.hpp"
#include "statics/factor_preconditioner.hpp"
#include "statics/hypre_amg.hpp"

namespace latmpm::statics {

namespace {
const std::array<std::pair<LinearSolverKind, const char*>, 5> solver_names{{{LinearSolverKind::ldlt, "ldlt"},
                                                                          {LinearSolverKind::cg, "cg"},
                                                                          {LinearSolverKind::cholmod, "cholmod"},
                                                                          {LinearSolverKind::amg, "amg"},
                                                                          {LinearSolverKind::automatic, "auto"}}};
}

std::string to_string(LinearSolverKind kind) { return mpm::name_table::name_of(kind, solver_names); }

std::vector<std::string> linear_solver_names() { return mpm::name_table::names_in(solver_names); }

LinearSolverKind parse_linear_solver(const std::string& name, const std::string& where, const std::string& field) {
  return mpm::name_table::parse_name(name, solver_names, where, field);
}

struct SparseSolver::Impl {
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<Real>> cg;
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, FactorPreconditioner> factor_cg;
  CholmodDirect cholmod;
  std::unique_ptr<HypreAmg> amg;  // made on first use: it initialises MPI
  std::vector<Vec3> node_positions;
  bool analysed = false;
  const SparseMatrix* matrix = nullptr;
};

SparseSolver::SparseSolver(LinearSolverKind kind, Real tolerance, int max_iterations)
    : kind_(kind), used_(kind), iterative_tolerance_(tolerance), iterative_max_iterations_(max_iterations),
      factor_memory_budget_(0.5 * double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE))),
      impl_(std::make_unique<Impl>()) {
  impl_->cg.setTolerance(tolerance);
  impl_->cg.setMaxIterations(max_iterations);
}

void SparseSolver::set_node_positions(std::vector<Vec3> positions) { impl_->node_positions = std::move(positions); }

SparseSolver::~SparseSolver() = default;

bool SparseSolver::factorize(const SparseMatrix& K) {
  const bool factorized = factorize_matrix(K);
  factor_valid_ = factorized && is_direct();  // a failed factorisation leaves a partial factor
  return factorized;
}

bool SparseSolver::factorize_matrix(const SparseMatrix& K) {
  Impl& s = *impl_;
  s.matrix = &K;
  if (used_ == LinearSolverKind::automatic) {  // CHOLMOD's symbolic analysis says how big L gets
    PhaseTimer timer(times_.analyse);
    s.cholmod.analyse(K);
    const double factor_bytes = s.cholmod.figures().factor_nonzeros * sizeof(Real);
    used_ = factor_bytes > factor_memory_budget_ ? LinearSolverKind::amg : LinearSolverKind::cholmod;
  }
  switch (used_) {
    case LinearSolverKind::ldlt:
      if (!s.analysed) {
        PhaseTimer timer(times_.analyse);
        s.ldlt.analyzePattern(K);
      }
      s.analysed = true;
      {
        PhaseTimer timer(times_.factorise);
        s.ldlt.factorize(K);
      }
      return s.ldlt.info() == Eigen::Success && s.ldlt.vectorD().minCoeff() > 0;
    case LinearSolverKind::cg: {
      PhaseTimer timer(times_.factorise);
      s.cg.compute(K);  // the incomplete factorisation is redone for each matrix
      return s.cg.info() == Eigen::Success;
    }
    case LinearSolverKind::cholmod: {
      if (!s.cholmod.analysed()) {
        PhaseTimer timer(times_.analyse);
        s.cholmod.analyse(K);
      }
      PhaseTimer timer(times_.factorise);
      return s.cholmod.factorize(K);
    }
    case LinearSolverKind::amg:
      if (!s.amg) {
        s.amg = std::make_unique<HypreAmg>(iterative_tolerance_, iterative_max_iterations_);
        s.amg->set_node_positions(s.node_positions);
      }
      {
        PhaseTimer timer(times_.factorise);
        s.amg->setup(K);
      }
      s.analysed = true;
      return true;
    case LinearSolverKind::automatic: break;
  }
  return false;
}

bool SparseSolver::solve_preconditioned(const SparseMatrix& K, const Vector& b, Real tolerance, int max_iterations,
                                        Vector& x, LinearSolveStats& stats) {
  if (!factor_valid_) return false;
  Impl& s = *impl_;
  PhaseTimer timer(times_.krylov);
  s.factor_cg.preconditioner().set([this](const Vector& r) {
    Impl& t = *impl_;
    return used_ == LinearSolverKind::ldlt ? Vector(t.ldlt.solve(r)) : t.cholmod.solve(r);
  });
  s.factor_cg.setTolerance(tolerance);
  s.factor_cg.setMaxIterations(max_iterations);
  s.factor_cg.compute(K);
  x = s.factor_cg.solve(b);
  stats.iterations = int(s.factor_cg.iterations());
  const Real norm_b = b.norm();  // the true residual, not CG's recurrence
  stats.relative_residual = norm_b > 0 ? (K * x - b).norm() / norm_b : Real(0);
  return s.factor_cg.info() == Eigen::Success && x.allFinite();
}

std::string SparseSolver::describe() const {
  const std::string chosen = kind_ == LinearSolverKind::automatic && used_ != kind_ ? "auto: " : "";
  if (used_ == LinearSolverKind::amg && impl_->amg) {
    const AmgFigures& f = impl_->amg->figures();
    return chosen + "amg (hypre BoomerAMG-preconditioned CG, nodal coarsening, " +
           (impl_->node_positions.empty() ? "no" : "3") + " rigid-body rotations, " + std::to_string(f.levels) +
           " levels, operator complexity " + format_number("%.2f", f.operator_complexity) + ")";
  }
  if (used_ != LinearSolverKind::cholmod || !impl_->cholmod.analysed()) return chosen + to_string(used_);
  const CholmodFigures& f = impl_->cholmod.figures();
  return chosen + "cholmod (supernodal, " + f.ordering + " ordering of the " + (f.node_ordering ? "node" : "unknown") +
         " graph, nnz(L) " + format_number("%.3g", f.factor_nonzeros) + ", " + format_number("%.3g", f.flops) +
         " flops per factorisation)";
}

Vector SparseSolver::solve(const Vector& b, LinearSolveStats& stats) {
  Impl& s = *impl_;
  PhaseTimer timer(times_.solve);
  Vector x;
  stats.iterations = 1;
  switch (used_) {
    case LinearSolverKind::ldlt: x = s.ldlt.solve(b); break;
    case LinearSolverKind::amg: {
      Real hypre_residual = 0;
      x = s.amg->solve(b, stats.iterations, hypre_residual);
      break;
    }
    case LinearSolverKind::automatic: throw std::logic_error("SparseSolver::solve before factorize");
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
