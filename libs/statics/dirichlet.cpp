#include "statics/dirichlet.hpp"

#include <algorithm>

#include "statics/static_shapes.hpp"

namespace latmpm::statics {

void Dirichlet::prescribe(size_t node, const Vec3& displacement) {
  for (int a = 0; a < 3; ++a) {
    fixed[3 * node + a] = 1;
    value[Eigen::Index(3 * node + a)] = displacement[a];
  }
}

size_t Dirichlet::count() const { return size_t(std::count(fixed.begin(), fixed.end(), char(1))); }

std::vector<size_t> nodes_reached_by(const NarrowBand& band, const std::vector<Vec3>& X,
                                     const std::vector<Vec3>& half_size) {
  std::vector<size_t> nodes;
  const Real inv_h = 1 / band.cell_size;
  with_static_shape(band.shape, [&](auto policy) {
    using Shape = decltype(policy);
    constexpr int N = Shape::nodes_per_axis;
    for (size_t p = 0; p < X.size(); ++p) {
      const auto s = mpm::make_stencil<Shape>(X[p], half_size[p], inv_h);
      for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j)
          for (int k = 0; k < N; ++k) {
            if (s.w[i][0] * s.w[j][1] * s.w[k][2] == 0) continue;
            const long n = band.find(Eigen::Vector3i(s.base[0] + i, s.base[1] + j, s.base[2] + k));
            if (n >= 0) nodes.push_back(size_t(n));
          }
    }
  });
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

void constrain_rows_and_columns(SparseMatrix& K, const std::vector<char>& fixed, Real diagonal) {
  for (int col = 0; col < K.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K, col); it; ++it)
      if (fixed[size_t(col)] || fixed[size_t(it.row())]) it.valueRef() = it.row() == col ? diagonal : Real(0);
}

Real mean_diagonal(const SparseMatrix& K) {
  const Real sum = K.diagonal().cwiseAbs().sum();
  return K.rows() > 0 && sum > 0 ? sum / Real(K.rows()) : Real(1);
}

}  // namespace latmpm::statics
