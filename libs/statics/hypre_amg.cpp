#include "statics/hypre_amg.hpp"

#include <HYPRE.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>
#include <_hypre_parcsr_ls.h>  // hypre_ParAMGData: levels and operator complexity for the log
#include <mpi.h>

#include <cstdlib>
#include <stdexcept>
#include <numeric>

#include "core/errors.hpp"
#include "core/number_text.hpp"

namespace latmpm::statics {

namespace {
// MPI and hypre once per process, finalised at exit (after every HypreAmg is gone: they
// live in objects destroyed before exit handlers run, or leak with the process).
void initialise_hypre() {
  static const bool done = [] {
    int mpi_ready = 0;
    MPI_Initialized(&mpi_ready);
    if (!mpi_ready) {
      MPI_Init(nullptr, nullptr);
      std::atexit([] {
        int finalised = 0;
        MPI_Finalized(&finalised);
        if (!finalised) MPI_Finalize();
      });
    }
    HYPRE_Init();
    std::atexit([] { HYPRE_Finalize(); });
    return true;
  }();
  (void)done;
}

HYPRE_IJVector make_vector(HYPRE_BigInt n, const Real* values) {
  HYPRE_IJVector v;
  HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, n - 1, &v);
  HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR);
  HYPRE_IJVectorInitialize(v);
  if (values) {
    std::vector<HYPRE_BigInt> rows(static_cast<size_t>(n));
    std::iota(rows.begin(), rows.end(), HYPRE_BigInt(0));
    HYPRE_IJVectorSetValues(v, HYPRE_Int(n), rows.data(), values);
  }
  HYPRE_IJVectorAssemble(v);
  return v;
}

HYPRE_ParVector par(HYPRE_IJVector v) {
  void* object = nullptr;
  HYPRE_IJVectorGetObject(v, &object);
  return static_cast<HYPRE_ParVector>(object);
}
}  // namespace

struct HypreAmg::Impl {
  HYPRE_IJMatrix matrix = nullptr;
  HYPRE_Solver amg = nullptr;
  HYPRE_Solver pcg = nullptr;
  std::vector<HYPRE_IJVector> rotations;    // the rigid-body rotations, and the array of
  std::vector<HYPRE_ParVector> interp_vectors;  // them hypre keeps a pointer to: live with amg
  HYPRE_BigInt size = 0;

  void release() {
    if (pcg) HYPRE_ParCSRPCGDestroy(pcg);
    if (amg) HYPRE_BoomerAMGDestroy(amg);
    if (matrix) HYPRE_IJMatrixDestroy(matrix);
    for (HYPRE_IJVector v : rotations) HYPRE_IJVectorDestroy(v);
    pcg = amg = nullptr;
    matrix = nullptr;
    rotations.clear();
    interp_vectors.clear();
  }
  ~Impl() { release(); }
};

HypreAmg::HypreAmg(Real tolerance, int max_iterations)
    : impl_(std::make_unique<Impl>()), tolerance_(tolerance), max_iterations_(max_iterations) {
  initialise_hypre();
}

HypreAmg::~HypreAmg() = default;

void HypreAmg::setup(const SparseMatrix& K) {
  Impl& s = *impl_;
  s.release();
  const HYPRE_BigInt n = K.rows();
  s.size = n;
  // K is stored symmetric in full, so column j is row j: hypre's CSR rows are Eigen's columns.
  HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, n - 1, 0, n - 1, &s.matrix);
  HYPRE_IJMatrixSetObjectType(s.matrix, HYPRE_PARCSR);
  std::vector<HYPRE_Int> row_sizes(static_cast<size_t>(n));
  for (Eigen::Index j = 0; j < n; ++j) row_sizes[size_t(j)] = HYPRE_Int(K.outerIndexPtr()[j + 1] - K.outerIndexPtr()[j]);
  HYPRE_IJMatrixSetRowSizes(s.matrix, row_sizes.data());
  HYPRE_IJMatrixInitialize(s.matrix);
  std::vector<HYPRE_BigInt> rows(static_cast<size_t>(n));
  std::iota(rows.begin(), rows.end(), HYPRE_BigInt(0));
  static_assert(sizeof(HYPRE_BigInt) == sizeof(int), "K's indices are handed to hypre as they are");
  HYPRE_IJMatrixSetValues(s.matrix, HYPRE_Int(n), row_sizes.data(), rows.data(),
                          reinterpret_cast<const HYPRE_BigInt*>(K.innerIndexPtr()), K.valuePtr());
  HYPRE_IJMatrixAssemble(s.matrix);
  void* object = nullptr;
  HYPRE_IJMatrixGetObject(s.matrix, &object);
  auto A = static_cast<HYPRE_ParCSRMatrix>(object);

  // BoomerAMG as one V-cycle per PCG iteration, with the options hypre's users take for
  // elasticity (MFEM's HypreBoomerAMG::SetElasticityOptions): HMIS coarsening, extended+i
  // interpolation truncated to 4 entries a row, ℓ1 Gauss–Seidel (symmetric, as PCG needs).
  HYPRE_BoomerAMGCreate(&s.amg);
  HYPRE_BoomerAMGSetPrintLevel(s.amg, 0);
  HYPRE_BoomerAMGSetMaxIter(s.amg, 1);
  HYPRE_BoomerAMGSetTol(s.amg, 0.0);
  HYPRE_BoomerAMGSetCoarsenType(s.amg, 10);
  HYPRE_BoomerAMGSetInterpType(s.amg, 6);
  HYPRE_BoomerAMGSetPMaxElmts(s.amg, 4);
  HYPRE_BoomerAMGSetRelaxType(s.amg, 8);
  HYPRE_BoomerAMGSetCycleRelaxType(s.amg, 8, 3);  // coarsest level too (hypre's default there is a direct solve)
  HYPRE_BoomerAMGSetAggNumLevels(s.amg, 0);
  HYPRE_BoomerAMGSetStrongThreshold(s.amg, 0.5);
  HYPRE_BoomerAMGSetNumFunctions(s.amg, 3);
  HYPRE_BoomerAMGSetNodal(s.amg, 4);
  HYPRE_BoomerAMGSetNodalDiag(s.amg, 1);
  if (!positions_.empty()) {
    if (HYPRE_BigInt(3 * positions_.size()) != n)
      throw std::logic_error("HypreAmg: " + std::to_string(positions_.size()) + " node positions for " +
                          std::to_string(n) + " unknowns");
    Vec3 centre = Vec3::Zero();
    for (const Vec3& x : positions_) centre += x;
    centre /= Real(positions_.size());
    std::vector<Real> values(static_cast<size_t>(n));
    for (int axis = 0; axis < 3; ++axis) {  // u = e_axis × (x − centre): the rotations
      for (size_t i = 0; i < positions_.size(); ++i) {
        const Vec3 x = positions_[i] - centre;
        Vec3 r = Vec3::Zero();  // e_axis × x
        r[(axis + 1) % 3] = -x[(axis + 2) % 3];
        r[(axis + 2) % 3] = x[(axis + 1) % 3];
        for (int c = 0; c < 3; ++c) values[3 * i + size_t(c)] = r[c];
      }
      s.rotations.push_back(make_vector(n, values.data()));
    }
    for (HYPRE_IJVector v : s.rotations) s.interp_vectors.push_back(par(v));
    HYPRE_BoomerAMGSetInterpVecVariant(s.amg, 2);
    HYPRE_BoomerAMGSetInterpVecQMax(s.amg, 4);
    HYPRE_BoomerAMGSetSmoothInterpVectors(s.amg, 1);
    HYPRE_BoomerAMGSetInterpRefine(s.amg, 1);
    HYPRE_BoomerAMGSetInterpVectors(s.amg, HYPRE_Int(s.interp_vectors.size()), s.interp_vectors.data());
  }

  HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &s.pcg);
  HYPRE_PCGSetTol(s.pcg, tolerance_);
  HYPRE_PCGSetMaxIter(s.pcg, max_iterations_);
  HYPRE_PCGSetTwoNorm(s.pcg, 1);
  HYPRE_PCGSetPrintLevel(s.pcg, 0);
  HYPRE_PCGSetPrecond(s.pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                      reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), s.amg);
  HYPRE_IJVector b = make_vector(n, nullptr), x = make_vector(n, nullptr);
  HYPRE_ParCSRPCGSetup(s.pcg, A, par(b), par(x));  // builds the AMG hierarchy
  HYPRE_IJVectorDestroy(b);
  HYPRE_IJVectorDestroy(x);

  auto* data = static_cast<hypre_ParAMGData*>(static_cast<void*>(s.amg));
  figures_.levels = hypre_ParAMGDataNumLevels(data);
  double total = 0;
  for (int l = 0; l < figures_.levels; ++l) {
    hypre_ParCSRMatrix* level = hypre_ParAMGDataAArray(data)[l];
    total += double(hypre_CSRMatrixNumNonzeros(hypre_ParCSRMatrixDiag(level)));
  }
  figures_.operator_complexity = total / double(hypre_CSRMatrixNumNonzeros(hypre_ParCSRMatrixDiag(
                                             hypre_ParAMGDataAArray(data)[0])));
}

Vector HypreAmg::solve(const Vector& b, int& iterations, Real& relative_residual) {
  Impl& s = *impl_;
  if (!s.pcg) throw std::logic_error("HypreAmg::solve before setup");
  HYPRE_IJVector rhs = make_vector(s.size, b.data()), x = make_vector(s.size, nullptr);
  void* object = nullptr;
  HYPRE_IJMatrixGetObject(s.matrix, &object);
  HYPRE_ParCSRPCGSolve(s.pcg, static_cast<HYPRE_ParCSRMatrix>(object), par(rhs), par(x));
  HYPRE_Int its = 0, converged = 0;
  HYPRE_Real residual = 0;
  HYPRE_PCGGetNumIterations(s.pcg, &its);
  HYPRE_PCGGetFinalRelativeResidualNorm(s.pcg, &residual);
  HYPRE_PCGGetConverged(s.pcg, &converged);
  HYPRE_ClearAllErrors();  // non-convergence is reported below, not left in hypre's flag
  iterations = int(its);
  relative_residual = residual;
  Vector result(b.size());
  std::vector<HYPRE_BigInt> rows(static_cast<size_t>(s.size));
  std::iota(rows.begin(), rows.end(), HYPRE_BigInt(0));
  HYPRE_IJVectorGetValues(x, HYPRE_Int(s.size), rows.data(), result.data());
  HYPRE_IJVectorDestroy(rhs);
  HYPRE_IJVectorDestroy(x);
  if (!converged)
    throw NumericalError("static solve: AMG-preconditioned CG did not converge in " + std::to_string(its) +
                         " iterations (relative residual " + format_number("%.3g", residual) + ")");
  return result;
}

}  // namespace latmpm::statics
