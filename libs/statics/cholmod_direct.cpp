#include "statics/cholmod_direct.hpp"

#include <cholmod.h>

#include <Eigen/CholmodSupport>
#include <vector>

#include "core/blas_threads.hpp"
#include "core/errors.hpp"

namespace latmpm::statics {

struct CholmodDirect::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  Impl() {
    cholmod_start(&common);
    common.print = 0;  // a non-positive-definite matrix is an answer, not a warning
    common.supernodal = CHOLMOD_SUPERNODAL;
  }
  ~Impl() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
};

namespace {
const char* ordering_name(int ordering) {
  switch (ordering) {
    case CHOLMOD_NATURAL: return "natural";
    case CHOLMOD_GIVEN: return "given";
    case CHOLMOD_AMD: return "amd";
    case CHOLMOD_METIS: return "metis";
    case CHOLMOD_NESDIS: return "nesdis";
    case CHOLMOD_COLAMD: return "colamd";
    case CHOLMOD_POSTORDERED: return "postordered";
  }
  return "?";
}

// Whether K consists of full 3×3 blocks (node n: unknowns 3n..3n+2): columns 3n, 3n+1, 3n+2
// share one pattern whose rows come in whole aligned triplets.
bool has_node_blocks(const SparseMatrix& K) {
  if (K.rows() % 3 != 0 || !K.isCompressed()) return false;
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  for (Eigen::Index n = 0; n < K.cols() / 3; ++n) {
    const int begin = outer[3 * n], size = outer[3 * n + 1] - begin;
    if (size % 3 != 0) return false;
    for (int a = 1; a < 3; ++a)
      if (outer[3 * n + a + 1] - outer[3 * n + a] != size ||
          !std::equal(inner + begin, inner + begin + size, inner + outer[3 * n + a]))
        return false;
    for (int k = 0; k < size; k += 3)
      if (inner[begin + k] % 3 != 0 || inner[begin + k + 1] != inner[begin + k] + 1 ||
          inner[begin + k + 2] != inner[begin + k] + 2)
        return false;
  }
  return true;
}
}  // namespace

CholmodDirect::CholmodDirect() : impl_(std::make_unique<Impl>()) {}
CholmodDirect::~CholmodDirect() = default;
bool CholmodDirect::analysed() const { return impl_->factor != nullptr; }

void CholmodDirect::analyse(const SparseMatrix& K) {
  cholmod_common& c = impl_->common;
  if (impl_->factor) cholmod_free_factor(&impl_->factor, &c);
  cholmod_sparse A = Eigen::viewAsCholmod(K.selfadjointView<Eigen::Lower>());
  figures_ = {};
  if (has_node_blocks(K)) {
    // The node graph's lower triangle (pattern only), ordered with CHOLMOD's default
    // strategy (AMD, then METIS where AMD's fill is high).
    const Eigen::Index nodes = K.cols() / 3;
    std::vector<int> outer(size_t(nodes) + 1, 0), inner;
    inner.reserve(size_t(K.nonZeros() / 18 + nodes));
    for (Eigen::Index n = 0; n < nodes; ++n) {
      for (int k = K.outerIndexPtr()[3 * n]; k < K.outerIndexPtr()[3 * n + 1]; k += 3)
        if (K.innerIndexPtr()[k] / 3 >= n) inner.push_back(K.innerIndexPtr()[k] / 3);
      outer[size_t(n) + 1] = int(inner.size());
    }
    cholmod_sparse G{};
    G.nrow = G.ncol = size_t(nodes);
    G.nzmax = inner.size();
    G.p = outer.data();
    G.i = inner.data();
    G.stype = -1;
    G.itype = CHOLMOD_INT;
    G.xtype = CHOLMOD_PATTERN;
    G.dtype = CHOLMOD_DOUBLE;
    G.sorted = 1;
    G.packed = 1;
    cholmod_factor* node_factor = cholmod_analyze(&G, &c);
    if (!node_factor) throw NumericalError("CHOLMOD could not order the node graph (status " + std::to_string(c.status) + ")");
    figures_.ordering = ordering_name(c.method[c.selected].ordering);
    const int* node_perm = static_cast<const int*>(node_factor->Perm);
    std::vector<int> perm(size_t(K.cols()));
    for (Eigen::Index k = 0; k < nodes; ++k)
      for (int a = 0; a < 3; ++a) perm[size_t(3 * k + a)] = 3 * node_perm[k] + a;
    cholmod_free_factor(&node_factor, &c);
    const int saved_methods = c.nmethods, saved_ordering = c.method[0].ordering;
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_GIVEN;
    impl_->factor = cholmod_analyze_p(&A, perm.data(), nullptr, 0, &c);
    c.nmethods = saved_methods;
    c.method[0].ordering = saved_ordering;
    figures_.node_ordering = true;
  } else {
    impl_->factor = cholmod_analyze(&A, &c);
    figures_.ordering = ordering_name(c.method[c.selected].ordering);
  }
  if (!impl_->factor) throw NumericalError("CHOLMOD could not analyse the matrix (status " + std::to_string(c.status) + ")");
  figures_.factor_nonzeros = c.lnz;
  figures_.flops = c.fl;
}

bool CholmodDirect::factorize(const SparseMatrix& K) {
  if (!impl_->factor) analyse(K);
  cholmod_sparse A = Eigen::viewAsCholmod(K.selfadjointView<Eigen::Lower>());
  const auto threads = BlasThreadLimit::for_flops(figures_.flops);
  cholmod_factorize(&A, impl_->factor, &impl_->common);
  if (impl_->common.status == CHOLMOD_OUT_OF_MEMORY)
    throw NumericalError("CHOLMOD ran out of memory factorising a " + std::to_string(K.rows()) + "-unknown matrix");
  return impl_->factor->minor == impl_->factor->n;
}

Vector CholmodDirect::solve(const Vector& b) {
  Vector rhs = b;
  cholmod_dense B = Eigen::viewAsCholmod(rhs);
  cholmod_dense* X = cholmod_solve(CHOLMOD_A, impl_->factor, &B, &impl_->common);
  if (!X) throw NumericalError("CHOLMOD solve failed (status " + std::to_string(impl_->common.status) + ")");
  Vector x = Eigen::Map<const Vector>(static_cast<const double*>(X->x), Eigen::Index(b.size()));
  cholmod_free_dense(&X, &impl_->common);
  return x;
}

}  // namespace latmpm::statics
