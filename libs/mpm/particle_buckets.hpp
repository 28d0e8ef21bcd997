// Particles grouped by bucket: a cube of 8×8×8 grid cells. The particle arrays are sorted
// by (bucket, body, cell), so a bucket is one contiguous range and, inside it, each body is
// one run (the material model is chosen once per run, not per particle).
//
// Why buckets: P2G scatters each bucket into a small dense buffer (fast, fixed strides) and
// adds the buffer to the sparse grid afterwards. Buckets of the same colour (parity of the
// bucket coordinates, 8 colours) are two buckets apart, so their buffers never overlap and
// can be added in parallel without atomics — and in a fixed order, so results do not depend
// on the thread count. A particle may drift up to one cell out of its bucket before the
// particles are re-sorted; the buffer (14 nodes per axis) covers that drift.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "mpm/particles.hpp"
#include "mpm/real.hpp"

namespace latmpm::mpm {

struct BodyRun {
  int32_t body;
  uint32_t begin, end;  // particle index range
};

struct Bucket {
  std::array<int, 3> coord;  // bucket coordinates: cells [8·coord, 8·coord + 7]
  uint32_t begin, end;       // particle index range
  uint32_t run_begin, run_end;  // range in ParticleBuckets::runs
  // Node box the stencils of this bucket's particles reach this step (inclusive), in node
  // coordinates; always inside [8·coord − 2, 8·coord + 11] (drift limit).
  std::array<int, 3> box_lo, box_hi;
};

class ParticleBuckets {
 public:
  static constexpr int cells = 8;           // bucket width in cells
  static constexpr int max_drift = 1;       // cells a particle may leave its bucket by
  static constexpr int buffer_width = cells + 2 * max_drift + 4;  // 14 nodes per axis
  static constexpr int buffer_lo = -2;      // buffer's first node relative to 8·coord

  // Sorts the particles (all arrays) by (bucket, body, cell) and rebuilds buckets and runs.
  // Ties keep the particles' id order, so the result is the same for any thread count.
  void sort(Particles& particles, Real cell_size);
  // Takes buckets and runs as saved from an earlier run (checkpoints), the particles being
  // in the order they had then; boxes are left for the caller. Colours are rebuilt.
  void restore(std::vector<Bucket> buckets, std::vector<BodyRun> runs);

  const std::vector<Bucket>& buckets() const { return buckets_; }
  std::vector<Bucket>& buckets() { return buckets_; }
  const std::vector<BodyRun>& runs() const { return runs_; }
  // Bucket indices of each of the 8 colours.
  const std::array<std::vector<uint32_t>, 8>& colours() const { return colours_; }

  // True if a particle in cell `cell` may stay in the bucket: at most max_drift cells out.
  static bool within_drift(const Bucket& b, const std::array<int, 3>& cell) {
    for (int a = 0; a < 3; ++a)
      if (cell[a] < cells * b.coord[a] - max_drift || cell[a] > cells * b.coord[a] + cells - 1 + max_drift)
        return false;
    return true;
  }

 private:
  std::vector<Bucket> buckets_;
  std::vector<BodyRun> runs_;
  std::array<std::vector<uint32_t>, 8> colours_;
  std::vector<uint64_t> keys_;
  std::vector<uint32_t> order_;
};

// The cell containing x (cell c spans [c·h, (c+1)·h)).
inline std::array<int, 3> cell_of(const Vec3& x, Real inv_h) {
  return {int(std::floor(x[0] * inv_h)), int(std::floor(x[1] * inv_h)), int(std::floor(x[2] * inv_h))};
}

}  // namespace latmpm::mpm
