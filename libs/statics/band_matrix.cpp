#include "statics/band_matrix.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace latmpm::statics {

namespace {
int slot_of(const Eigen::Vector3i& d, int reach, int span) {
  return ((d[2] + reach) * span + d[1] + reach) * span + d[0] + reach;
}
}  // namespace

BandMatrix::BandMatrix(const NarrowBand& band) : band_(band) {
  const int reach = band.nodes_per_axis - 1;
  span_ = 2 * reach + 1;
  const int slots = span_ * span_ * span_;
  const size_t nodes = band.node_count();
  slot_position_.assign(nodes * slots, -1);
  neighbor_offset_.assign(nodes + 1, 0);
  // Mark the neighbours, then number them in slot order, which is band order: both sort
  // by (k, j, i).
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nodes, 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t n = r.begin(); n < r.end(); ++n) {
      int* slot = slot_position_.data() + n * slots;
      for (uint32_t k = band.node_entry_offset[n]; k < band.node_entry_offset[n + 1]; ++k) {
        const uint32_t p = band.entry_point[band.node_entry[k]];
        for (uint32_t e = band.point_offset[p]; e < band.point_offset[p + 1]; ++e)
          slot[slot_of(band.node[band.entry_node[e]] - band.node[n], reach, span_)] = 0;
      }
      int count = 0;
      for (int s = 0; s < slots; ++s)
        if (slot[s] == 0) slot[s] = count++;
      neighbor_offset_[n + 1] = count;
    }
  });
  for (size_t n = 0; n < nodes; ++n) neighbor_offset_[n + 1] += neighbor_offset_[n];

  const long dofs = long(3 * nodes);
  matrix_.resize(dofs, dofs);
  matrix_.resizeNonZeros(9 * long(neighbor_offset_[nodes]));
  int* outer = matrix_.outerIndexPtr();
  int* inner = matrix_.innerIndexPtr();
  outer[0] = 0;
  for (size_t n = 0; n < nodes; ++n) {
    const int degree = neighbor_offset_[n + 1] - neighbor_offset_[n];
    // Neighbour band indices in order, from the slots.
    std::vector<int> neighbors(size_t(degree), 0);
    const int* slot = slot_position_.data() + n * slots;
    for (int s = 0; s < slots; ++s)
      if (slot[s] >= 0) {
        const Eigen::Vector3i d(s % span_ - reach, (s / span_) % span_ - reach, s / (span_ * span_) - reach);
        neighbors[size_t(slot[s])] = int(band.find(band.node[n] + d));
      }
    for (int a = 0; a < 3; ++a) {
      const int column = int(3 * n) + a;
      int at = outer[column];
      for (int j : neighbors)
        for (int c = 0; c < 3; ++c) inner[at++] = 3 * j + c;
      outer[column + 1] = at;
    }
  }
}

void BandMatrix::assemble(const std::function<void(size_t, Mat9&)>& tangent) {
  const NarrowBand& band = band_;
  const int reach = band.nodes_per_axis - 1, slots = span_ * span_ * span_;
  Real* values = matrix_.valuePtr();
  const int* outer = matrix_.outerIndexPtr();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, band.node_count(), 64), [&](const tbb::blocked_range<size_t>& r) {
    Mat9 A;
    for (size_t n = r.begin(); n < r.end(); ++n) {
      const int* slot = slot_position_.data() + n * slots;
      const int degree = neighbor_offset_[n + 1] - neighbor_offset_[n];
      Real* column[3];
      for (int a = 0; a < 3; ++a) {
        column[a] = values + outer[3 * n + a];
        std::fill(column[a], column[a] + 3 * degree, Real(0));
      }
      for (uint32_t k = band.node_entry_offset[n]; k < band.node_entry_offset[n + 1]; ++k) {
        const uint32_t own = band.node_entry[k], p = band.entry_point[own];
        const Vec3& gi = band.entry_gradient[own];
        tangent(p, A);
        // T_a,(cd) = Σ_b ∇S_i,b A_(ab)(cd): node i's row of the point's Hessian, per F entry.
        Eigen::Matrix<Real, 3, 9> T;
        for (int a = 0; a < 3; ++a)
          T.row(a) = gi[0] * A.row(3 * a) + gi[1] * A.row(3 * a + 1) + gi[2] * A.row(3 * a + 2);
        for (uint32_t e = band.point_offset[p]; e < band.point_offset[p + 1]; ++e) {
          const Vec3& gj = band.entry_gradient[e];
          const int pos = slot[slot_of(band.node[band.entry_node[e]] - band.node[n], reach, span_)];
          for (int a = 0; a < 3; ++a)
            for (int c = 0; c < 3; ++c)
              column[a][3 * pos + c] += T(a, 3 * c) * gj[0] + T(a, 3 * c + 1) * gj[1] + T(a, 3 * c + 2) * gj[2];
        }
      }
    }
  });
}

std::vector<Real> BandMatrix::assemble_blocks(const StencilRow& row) const {
  const NarrowBand& band = band_;
  const int reach = band.nodes_per_axis - 1, slots = span_ * span_ * span_;
  std::vector<Real> blocks(size_t(neighbor_offset_[band.node_count()]), Real(0));
  tbb::parallel_for(tbb::blocked_range<size_t>(0, band.node_count(), 64), [&](const tbb::blocked_range<size_t>& r) {
    std::vector<Real> values;
    for (size_t n = r.begin(); n < r.end(); ++n) {
      const int* slot = slot_position_.data() + n * slots;
      Real* column = blocks.data() + neighbor_offset_[n];
      for (uint32_t k = band.node_entry_offset[n]; k < band.node_entry_offset[n + 1]; ++k) {
        const uint32_t own = band.node_entry[k], p = band.entry_point[own];
        const uint32_t first = band.point_offset[p], count = band.point_offset[p + 1] - first;
        values.resize(count);
        row(p, own, values.data());
        for (uint32_t e = 0; e < count; ++e)
          column[slot[slot_of(band.node[band.entry_node[first + e]] - band.node[n], reach, span_)]] += values[e];
      }
    }
  });
  return blocks;
}

void BandMatrix::add_blocks(const std::vector<Real>& blocks) {
  Real* values = matrix_.valuePtr();
  const int* outer = matrix_.outerIndexPtr();
  tbb::parallel_for(size_t(0), band_.node_count(), [&](size_t n) {
    const int first = neighbor_offset_[n], degree = neighbor_offset_[n + 1] - first;
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < degree; ++k) values[outer[3 * n + a] + 3 * k + a] += blocks[size_t(first + k)];
  });
}

void BandMatrix::multiply_blocks(const std::vector<Real>& blocks, const Eigen::Matrix<Real, Eigen::Dynamic, 1>& u,
                                 Eigen::Matrix<Real, Eigen::Dynamic, 1>& f) const {
  const int* outer = matrix_.outerIndexPtr();
  const int* inner = matrix_.innerIndexPtr();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, band_.node_count(), 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t n = r.begin(); n < r.end(); ++n) {
      const int first = neighbor_offset_[n], degree = neighbor_offset_[n + 1] - first;
      Vec3 sum = Vec3::Zero();
      for (int k = 0; k < degree; ++k)  // the block's node: the column's k-th row triplet
        sum += blocks[size_t(first + k)] * u.segment<3>(inner[outer[3 * n] + 3 * k]);
      f.segment<3>(Eigen::Index(3 * n)) += sum;
    }
  });
}

}  // namespace latmpm::statics
