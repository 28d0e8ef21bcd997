// DDMP's small-mass nodes (the DDMP group's treatment; docs/solver.md, "DDMP").
//
// Small-mass nodes (Zhang, Ma & Giguere 2011, the nodal transfer coefficients C_li; the
// "distribution coefficient algorithm" of DDMP implementations): the smoothed force reaches
// the nodes one cell outside the material, which have no mass, and a particle that has just
// entered a cell gives its far nodes a mass that vanishes with its distance to the face
// while its α∇S force does not vanish as fast (α ~ d^{2/7}). Such a node l (mass below a
// fraction of ρ h³, not held by a body — or held, but with no mass at all: inside a rigid
// plate of points) gets no acceleration of its own: its mass, momentum
// and force go to the sizeable nodes i around it with coefficients C_li, and after the grid
// update its velocity and velocity change are read back, v_l = Σ_i C_li v_i. The same C
// both ways with Σ_i C_li = 1 keeps mass, momentum and force exactly and makes the
// particles' momentum change equal to the total force; Σ_i C_li x_i = x_l (a linear fit,
// find_ddmp_small_mass_nodes) makes a linear velocity field read back exactly, so the
// smoothed velocity gradient of a surface node sees no spurious shear. Which nodes hand on,
// and their coefficients, live in DdmpNodalValues (ddmp_grid.hpp).
#pragma once
#include <tbb/concurrent_unordered_map.h>
#include <tbb/parallel_for.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <type_traits>
#include <vector>

#include "core/large_pages.hpp"
#include "mpm/ddmp_grid.hpp"
#include "mpm/simd.hpp"

namespace latmpm::mpm {

namespace ddmp_grid_detail {
constexpr int reach = 2;  // the neighbourhood of a small-mass node: offsets −2 … 2 per axis

// w(d) = 2^(−|d|₁) of an offset d within reach.
inline Real offset_weight(int x, int y, int z) {
  static constexpr Real w[3 * reach + 1] = {1, 0.5, 0.25, 0.125, 0.0625, 0.03125, 0.015625};
  return w[std::abs(x) + std::abs(y) + std::abs(z)];
}
// Bit of offset d in a node's 5×5×5 neighbourhood: bit z + 2 of byte (x + 2)·5 + (y + 2), a
// byte per column (x, y) of offsets along z (NeighbourPattern).
constexpr int box_bit(int x, int y, int z) { return ((x + reach) * (2 * reach + 1) + (y + reach)) * 8 + (z + reach); }
constexpr int own_mass_bit = box_bit(0, 0, 0);
// The 124 offsets d ≠ 0 within two cells per axis: a node one cell outside a flat face sees
// two layers of the material along the normal (a linear fit), and every node next to a
// particle's cell sees sizeable nodes even where a particle has just entered a new cell.
struct Offset {
  int x, y, z;
  Real weight;   // 2^(−|d|₁)
  bool nearest;  // |d|₁ ≤ 2 (Receivers::nearest)
};
constexpr int offset_count = 124;
inline const std::array<Offset, offset_count>& neighbour_offsets() {
  static const auto list = [] {
    std::array<Offset, offset_count> out{};
    size_t n = 0;
    for (int x = -reach; x <= reach; ++x)
      for (int y = -reach; y <= reach; ++y)
        for (int z = -reach; z <= reach; ++z) {
          const int l1 = std::abs(x) + std::abs(y) + std::abs(z);
          if (l1 > 0) out[n++] = {x, y, z, offset_weight(x, y, z), l1 <= 2};
        }
    return out;
  }();
  return list;
}
// The pattern of a small-mass node's neighbourhood: bit box_bit(d) set when the neighbour at
// offset d is sizeable, bit own_mass_bit when the node holds mass of its own. Its
// distribution coefficients are a function of this alone (fit_distribution). A byte per
// column (x, y) of the 5×5 offsets, its bits 0–4 the offsets z = −2 … 2 (25 bytes in four
// words): the pattern of a node is its column bytes of the block's rows shifted by the node's
// z, word by word (MaskHalo::columns, find_ddmp_small_mass_nodes).
struct NeighbourPattern {
  static constexpr int words = 4;
  std::array<uint64_t, words> bits{};
  bool operator==(const NeighbourPattern& o) const {  // four words, not a call of memcmp (1 % of a step)
    return ((bits[0] ^ o.bits[0]) | (bits[1] ^ o.bits[1]) | (bits[2] ^ o.bits[2]) | (bits[3] ^ o.bits[3])) == 0;
  }
  bool has(int bit) const { return (bits[size_t(bit >> 6)] >> (bit & 63)) & 1; }
  void set(int bit) { bits[size_t(bit >> 6)] |= uint64_t(1) << (bit & 63); }
  bool sizeable(const Offset& d) const { return has(box_bit(d.x, d.y, d.z)); }
};
struct NeighbourPatternHash {
  size_t operator()(const NeighbourPattern& p) const {
    // Every bit reaches the low bits the table indexes by (splitmix64's finaliser): a plain
    // product leaves them a function of the low pattern bits only (one slope of a face).
    const auto mix = [](uint64_t x) {
      x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
      x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
      return x ^ (x >> 31);
    };
    uint64_t h = 0;
    for (uint64_t w : p.bits) h = mix(h + w + 0x9E3779B97F4A7C15ull);
    return size_t(h);
  }
};
using Fit = std::array<Real, 4>;
}  // namespace ddmp_grid_detail

// A pattern's shares C_li = w(d)(c₀ + c · d) for the sizeable neighbours: the hand-on and
// the read-back visit these, not all 124 offsets (for_each_share). Per share its coefficient
// and its receiver's step in a block's BlockNodeIndex from the handing node, in the
// neighbour_offsets order, 10 bytes a share, in one allocation with this header
// (DistributionStorage): a paper-size lattice has ≈ 54,000 patterns, and with the shares in
// two vectors of their own every handing node began with three scattered misses — two
// fifths of the hand-on's and the read-back's samples sat on those loads (perf, T2P20-E8,
// 2026-11-28). Computing the shares from the fit instead cost 11 % more instructions on a
// QUICK lattice.
struct DdmpDistribution {
  ddmp_grid_detail::NeighbourPattern pattern;  // the neighbourhood it belongs to
  const Real* shares = nullptr;                // `count` coefficients, right after this header
  const int16_t* steps = nullptr;              // `count` steps, after the coefficients
  uint32_t count = 0;                          // none: the node does not hand on
  bool hands_on() const { return count != 0; }
};

namespace ddmp_grid_detail {

// The first lines of a distribution (its header and first coefficients), which
// prefetch_distributions asks for with its block.
inline constexpr int block_prefetched_lines = 2;
// Asks for the rest of a distribution's shares (its coefficients and steps, ≈ 8 lines in all):
// the read-back asks for them a pair of nodes ahead (for_each_share_pair). perf side by side,
// both orders, against G2P (unchanged): the read-back 10–13 % faster; the same in the hand-on
// made it 7 % slower (its receivers' writes compete with the requests), so it is not used
// there (QUICK T2P30, 2026-11-29).
inline void prefetch_shares(const DdmpDistribution& d) {
  const char* line = reinterpret_cast<const char*>(&d) + 64 * block_prefetched_lines;
  const char* end = reinterpret_cast<const char*>(d.steps + d.count);
  for (; line < end; line += 64) __builtin_prefetch(line);
}
// The nodes of a block and its halo of `reach` nodes: their indices in the grid's node order
// (block · 64 + node), halo node (a, b, c) at a · 64 + b · 8 + c for local (a, b, c) − reach.
// Built once per block by the hand-on and the read-back, so that a share's receiver is one
// look-up. Entries in inactive blocks are meaningless (no share reaches them: sizeable nodes
// are active).
struct BlockNodeIndex {
  static constexpr int width = 8;
  static_assert(width == bw + 2 * reach, "the halo of a block is 8 nodes a side");
  uint32_t node[width * width * width];
  static int at(int i, int j, int k) { return ((i + reach) * width + (j + reach)) * width + (k + reach); }
  // The entry of the block's node n (n = (i·4 + j)·4 + k).
  static int of_node(int n) { return at(n >> 4, (n >> 2) & 3, n & 3); }
};
// A line of 8 indices along z at a time: `reach` from the block below, the block's own 4,
// `reach` from the block above.
inline void load_block_node_index(const DdmpNodalValues& nv, size_t b, BlockNodeIndex& index) {
  static_assert(reach == 2 && bw == 4, "a line is 2 + 4 + 2 nodes");
  typedef uint32_t Line __attribute__((vector_size(BlockNodeIndex::width * sizeof(uint32_t))));
  const auto& nb = nv.neighbours[b];
  uint32_t first_node[27];  // of the blocks around, in neighbour_index order (z fastest)
  for (size_t q = 0; q < 27; ++q) first_node[q] = uint32_t(nb[q] < 0 ? 0 : nb[q]) * uint32_t(SparseGrid::nodes_per_block);
  const Line local_k = {2, 3, 0, 1, 2, 3, 0, 1};
  for (int hi = 0; hi < BlockNodeIndex::width; ++hi)
    for (int hj = 0; hj < BlockNodeIndex::width; ++hj) {
      const int dx = hi < reach ? -1 : hi < reach + bw ? 0 : 1, dy = hj < reach ? -1 : hj < reach + bw ? 0 : 1;
      const uint32_t* column = first_node + neighbour_index(dx, dy, -1);  // below, at, above
      const Line blocks = {column[0], column[0], column[1], column[1], column[1], column[1], column[2], column[2]};
      const Line line = blocks + uint32_t((((hi + reach) & 3) * bw + ((hj + reach) & 3)) * bw) + local_k;
      std::memcpy(index.node + (hi * BlockNodeIndex::width + hj) * BlockNodeIndex::width, &line, sizeof line);
    }
}
// The step in BlockNodeIndex of the offset d.
constexpr int16_t box_index_step(int x, int y, int z) {
  return int16_t((x * BlockNodeIndex::width + y) * BlockNodeIndex::width + z);
}
// Calls fn(receiver, C_li) for the shares of the distribution of node n of the block whose
// BlockNodeIndex is `index`, in order; receiver is the node's index in the grid.
// Inlined, so that a sum fn keeps over the shares stays in registers: called out of line,
// the read-back's eight-lane sum went through the stack at every share on AVX2 (a
// store-forwarding stall each; docs/benchmarks.md, "Eight-lane splats on AVX2").
template <class Fn>
[[gnu::always_inline]] inline void for_each_share(const DdmpDistribution& d, const BlockNodeIndex& index, int n, Fn&& fn) {
  const uint32_t* own = index.node + BlockNodeIndex::of_node(n);
  const Real* C = d.shares;
  const int16_t* step = d.steps;
  for (uint32_t s = 0; s < d.count; ++s) fn(size_t(own[step[s]]), C[s]);
}

// The read-back's sums Σ_i C_li node_i of the block's nodes in `mask`, two nodes at a time,
// their shares interleaved: add(sum, receiver, C) adds one share to a node's sum, and
// done(n, sum) takes node n's sum. Each sum is one chain of multiply-adds (≈ 50 shares with
// all 124 receivers, ≈ 14 with the nearest; 4 cycles each), and one node at a time left the
// core waiting on that chain: perf put the read-back's samples on the multiply-add and the
// next share's load (T2P20-E8, 2026-11-28, with all 124).
// Two chains overlap; each node's sum still adds its shares in their order from zero, so the
// bits are those of one node at a time.
template <class Add, class Done>
[[gnu::always_inline]] inline void for_each_share_pair(uint64_t mask, const DdmpDistribution* const* distribution,
                                                       const BlockNodeIndex& index, Add&& add, Done&& done) {
  // Share s of distribution d into a node's sum; own: the node's entry in the index.
  const auto share = [&](num::NodeSum& sum, const uint32_t* own, const DdmpDistribution& d, uint32_t s)
                         __attribute__((always_inline)) { add(sum, size_t(own[d.steps[s]]), d.shares[s]); };
  // The shares of the pair after this one asked for as this one begins (prefetch_shares).
  uint64_t ahead = mask;
  const auto ask_next = [&] {
    if (ahead) prefetch_shares(*distribution[__builtin_ctzll(ahead)]), ahead &= ahead - 1;
  };
  ask_next(), ask_next();
  while (mask) {
    ask_next(), ask_next();
    const int n0 = __builtin_ctzll(mask);
    mask &= mask - 1;
    const DdmpDistribution& d0 = *distribution[n0];
    const uint32_t* own0 = index.node + BlockNodeIndex::of_node(n0);
    num::NodeSum sum0;
    if (!mask) {
      for (uint32_t s = 0; s < d0.count; ++s) share(sum0, own0, d0, s);
      done(n0, sum0);
      return;
    }
    const int n1 = __builtin_ctzll(mask);
    mask &= mask - 1;
    const DdmpDistribution& d1 = *distribution[n1];
    const uint32_t* own1 = index.node + BlockNodeIndex::of_node(n1);
    num::NodeSum sum1;
    const uint32_t both = std::min(d0.count, d1.count);
    for (uint32_t s = 0; s < both; ++s) share(sum0, own0, d0, s), share(sum1, own1, d1, s);
    for (uint32_t s = both; s < d0.count; ++s) share(sum0, own0, d0, s);
    for (uint32_t s = both; s < d1.count; ++s) share(sum1, own1, d1, s);
    done(n0, sum0);
    done(n1, sum1);
  }
}

// The halves of a node (num::low_lanes, num::high_lanes) that hold lanes first … first + count − 1.
constexpr unsigned halves_of(int first, int count) {
  return (first < 4 ? num::low_lanes : 0u) | (first + count > 4 ? num::high_lanes : 0u);
}

// C_li for the neighbour i at offset d = i − l, weight w, of a node with coefficients c.
inline Real distribution_coefficient(const Real* c, int x, int y, int z, Real w) {
  return w * (c[0] + c[1] * x + c[2] * y + c[3] * z);
}

// Which sizeable neighbours a small-mass node hands on to: the nearest — the 24 offsets with
// |d|₁ ≤ 2 (the 6 face neighbours, the 12 edge neighbours, the 6 two cells away along an
// axis) — where they span 3D, else all 124 within two cells per axis. A node one cell
// outside a flat face then hands on to 6 nodes (the two layers below it along the normal
// and the four beside the first) instead of ≈ 50; outside a corner or a thin edge, where
// the nearest are coplanar or absent, to the wider set as before. Both fits are exact for
// linear fields. Why: at the paper's resolution a thin-strut lattice has more nodes handing
// on than nodes with mass (T2P30: 170,674 against 162,599), and with all 124 they held 32.5
// shares each, 5.5 million a pass; the nearest cut that to 2.3 million and DDMP's step on the
// whole T2P30 by 9 % (docs/benchmarks.md, "DDMP on the whole paper-resolution T2P30").
// (Session 31 tried the 26 within one cell, else a 5×3×3 slab along one axis: with those
// the DDMP column of test_mpm "[buckling][ddmp]" blew up; with these it passes. docs/solver.md.)
enum class Receivers : uint8_t { nearest, within_two_cells };
inline bool receives(const Offset& d, Receivers receivers) {
  return receivers == Receivers::within_two_cells || d.nearest;
}
struct DistributionFit {
  Fit coefficients{};  // (c₀, c); zero: the node does not hand on
  Receivers receivers = Receivers::nearest;
  bool spans = false;  // the receivers span 3D (else the coefficients are their weighted mean)
};

// (c₀, c) of the weighted least-squares fit over the pattern's sizeable neighbours among
// `receivers` (zero: none); the weighted mean where they do not span 3D or where a node with
// mass would give a neighbour a negative share (find_ddmp_small_mass_nodes).
inline DistributionFit fit_over(const NeighbourPattern& pattern, Receivers receivers) {
  const auto& offsets = neighbour_offsets();
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  for (const Offset& d : offsets) {
    if (!pattern.sizeable(d) || !receives(d, receivers)) continue;
    const Eigen::Vector4d basis(1, d.x, d.y, d.z);
    A.noalias() += d.weight * basis * basis.transpose();
  }
  if (!(A(0, 0) > 0)) return {{0, 0, 0, 0}, receivers, false};
  const Eigen::LDLT<Eigen::Matrix4d> ldlt(A);
  const Eigen::Vector4d diagonal = ldlt.vectorD();
  Eigen::Vector4d fit = Eigen::Vector4d::Zero();
  const bool spans = ldlt.info() == Eigen::Success && diagonal.minCoeff() > 1e-6 * diagonal.maxCoeff();
  if (spans) fit = ldlt.solve(Eigen::Vector4d(1, 0, 0, 0));
  // A node with mass hands it on too: a negative C_li could leave a receiver with none.
  // Such a node takes the weighted mean (a node outside the material has none).
  bool negative = false;
  if (pattern.has(own_mass_bit) && fit[0] != 0)
    for (const Offset& d : offsets)
      if (pattern.sizeable(d) && receives(d, receivers))
        negative |= distribution_coefficient(fit.data(), d.x, d.y, d.z, d.weight) < 0;
  if (fit[0] == 0 || negative) fit = Eigen::Vector4d(1 / A(0, 0), 0, 0, 0);
  return {{fit[0], fit[1], fit[2], fit[3]}, receivers, spans};
}
// The fit over the nearest receivers where they span 3D, else over all within two cells.
inline DistributionFit fit_distribution(const NeighbourPattern& pattern) {
  const DistributionFit nearest = fit_over(pattern, Receivers::nearest);
  return nearest.spans ? nearest : fit_over(pattern, Receivers::within_two_cells);
}

// Where the memo's distributions live: chunks of 4 MB on large pages (core/large_pages.hpp),
// filled in the order the patterns are first met, so that a surface's patterns lie together
// and a paper-size lattice's ≈ 30 MB of them take 15 TLB entries instead of ≈ 8,000. Emptied
// with the memo. Taking memory is rare after the first steps (a new pattern), so one lock.
class DistributionArena {
 public:
  static constexpr size_t chunk_bytes = size_t(4) << 20;
  ~DistributionArena() { clear(); }
  void* take(size_t bytes) {
    bytes = (bytes + 63) / 64 * 64;  // every distribution starts on a cache line
    const std::lock_guard<std::mutex> lock(mutex_);
    if (chunks_.empty() || used_ + bytes > chunk_size_) {
      chunk_size_ = std::max(chunk_bytes, bytes);
      chunks_.push_back(static_cast<std::byte*>(allocate_on_large_pages(chunk_size_)));
      used_ = 0;
    }
    void* p = chunks_.back() + used_;
    used_ += bytes;
    return p;
  }
  void clear() {
    for (std::byte* chunk : chunks_) std::free(chunk);
    chunks_.clear();
    used_ = chunk_size_ = 0;
  }

 private:
  std::mutex mutex_;
  std::vector<std::byte*> chunks_;
  size_t used_ = 0, chunk_size_ = 0;
};
inline DistributionArena& distribution_arena() {
  static DistributionArena arena;
  return arena;
}

// The distributions remembered: a surface has few patterns (a flat face, its edges and
// corners, a particle entering a cell), so the 4×4 solve and the shares are computed once
// per pattern, not once per node and step. Insert-only during a step and shared by the
// threads (entries never move); a pure function of the pattern, so results do not depend
// on which thread computed it, nor on when the memo was last emptied.
// A distribution and its shares in one allocation: the header, the coefficients, the steps.
class DistributionStorage {
 public:
  DistributionStorage(const NeighbourPattern& pattern, const DistributionFit& fit) {
    const auto& offsets = neighbour_offsets();
    const auto receiving = [&](const Offset& d) { return pattern.sizeable(d) && receives(d, fit.receivers); };
    uint32_t count = 0;
    if (fit.coefficients[0] != 0)
      for (const Offset& d : offsets) count += receiving(d);
    bytes_ = static_cast<std::byte*>(
        distribution_arena().take(sizeof(DdmpDistribution) + count * (sizeof(Real) + sizeof(int16_t))));
    auto* shares = reinterpret_cast<Real*>(bytes_ + sizeof(DdmpDistribution));
    auto* steps = reinterpret_cast<int16_t*>(shares + count);
    uint32_t s = 0;
    if (count)
      for (const Offset& d : offsets)
        if (receiving(d)) {
          shares[s] = distribution_coefficient(fit.coefficients.data(), d.x, d.y, d.z, d.weight);
          steps[s++] = box_index_step(d.x, d.y, d.z);
        }
    distribution_ = new (bytes_) DdmpDistribution{pattern, shares, steps, count};
  }
  const DdmpDistribution& distribution() const { return *distribution_; }

 private:
  static_assert(sizeof(DdmpDistribution) % alignof(Real) == 0, "the coefficients follow the header aligned");
  static_assert(std::is_trivially_destructible_v<DdmpDistribution>, "freed with its bytes, no destructor run");
  std::byte* bytes_ = nullptr;  // in distribution_arena(), freed when the memo is emptied
  const DdmpDistribution* distribution_ = nullptr;
};
using DistributionMemo = tbb::concurrent_unordered_map<NeighbourPattern, DistributionStorage, NeighbourPatternHash>;
// At most one entry a bucket: the map's default of four (oneTBB's max_load_factor) made every
// look-up that missed the threads' caches walk a list of ≈ 2–4 scattered nodes, a cache miss
// each; that walk held ≈ 0.4 of the find's samples in a profile of the paper-size T1P30
// impact (perf, 2026-11-29).
inline DistributionMemo& distribution_memo() {
  static DistributionMemo memo = [] {
    DistributionMemo m;
    m.max_load_factor(1);
    return m;
  }();
  return memo;
}
// A crushed lattice keeps making new patterns: the QUICK DDMP impact had gathered 1.8 GB of
// them by its end (2026-11-27). Past this many entries the memo is emptied between steps
// (find_ddmp_small_mass_nodes, before any pointer into it is taken). A step's own patterns
// must fit, or every step refits them all: the paper-size T2P30 lattice starts with ≈ 54,000
// (2026-11-27; with a limit of 2^14 its fits were 17 % of the step). At ≈ 0.3 kB a pattern
// (≈ 14 shares of 10 B, the header with its pattern, the map's node) the limit is ≈ 40 MB,
// 1.4 kB a pattern at most (124 shares).
// One memo for the process: Simulations step one at a time.
inline constexpr size_t distribution_memo_limit = size_t(1) << 17;

// Bumped whenever the memo is emptied: the threads' caches of it (below) are then stale.
inline std::atomic<uint64_t>& distribution_memo_generation() {
  static std::atomic<uint64_t> generation{1};
  return generation;
}
inline void clear_distribution_memo() {
  distribution_memo().clear();
  distribution_arena().clear();
  ++distribution_memo_generation();
}

inline const DdmpDistribution& memo_distribution(const NeighbourPattern& pattern) {
  DistributionMemo& memo = distribution_memo();
  const auto it = memo.find(pattern);
  if (it != memo.end()) return it->second.distribution();
  return memo.emplace(pattern, DistributionStorage(pattern, fit_distribution(pattern))).first->second.distribution();
}

// The memo's look-up behind a small direct-mapped cache per thread: the concurrent map's
// find was 6 % of a lattice step (QUICK T2P30, 2026-11-27), one hash and one compare here.
inline const DdmpDistribution& remembered_distribution(const NeighbourPattern& pattern) {
  struct Entry {
    NeighbourPattern pattern;
    const DdmpDistribution* distribution = nullptr;
    uint64_t generation = 0;
  };
  static constexpr size_t slots = 1024;
  thread_local std::array<Entry, slots> cache{};
  const uint64_t generation = distribution_memo_generation().load(std::memory_order_relaxed);
  Entry& e = cache[NeighbourPatternHash{}(pattern) & (slots - 1)];
  if (e.generation == generation && e.pattern == pattern) return *e.distribution;
  const DdmpDistribution& d = memo_distribution(pattern);
  e = {pattern, &d, generation};
  return d;
}

// Per block, 64-bit node masks (bit n = node n, n = (i·4 + j)·4 + k): a row along k of local
// (i, j) is the 4 bits from (i·4 + j)·4.
// Rows along z of a mask over a block's halo of `reach` nodes: row[hi][hj] bit hk for halo
// coordinates (local + reach), from the masks of the 27 blocks around (0 where inactive).
struct MaskHalo {
  static constexpr int width = bw + 2 * reach;
  static_assert(width == 8, "a line of rows is one 64-bit word");
  alignas(8) uint8_t row[width][width];

  // Row line hi as one word: byte hj is row[hi][hj].
  uint64_t line(int hi) const {
    uint64_t out;
    std::memcpy(&out, row[hi], sizeof out);
    return out;
  }
  // The rows around local column (i, j): byte (x + 2)·5 + (y + 2) is row[i + 2 + x][j + 2 + y],
  // x, y = −2 … 2 — a node (i, j, k)'s neighbourhood pattern (NeighbourPattern) once each byte
  // is shifted right by k and cut to its five bits.
  std::array<uint64_t, NeighbourPattern::words> columns(int i, int j) const {
    std::array<uint64_t, NeighbourPattern::words> out{};
    for (int x = 0; x <= 2 * reach; ++x) {
      const uint64_t piece = (line(i + x) >> (8 * j)) & 0xFF'FFFF'FFFFull;  // the five rows y = −2 … 2
      const int at = 40 * x;                                                // five bytes a column x
      out[size_t(at >> 6)] |= piece << (at & 63);
      if ((at & 63) > 24) out[size_t(at >> 6) + 1] |= piece >> (64 - (at & 63));
    }
    return out;
  }
  // Bit n = (i·4 + j)·4 + k set when a node within R cells of local node (i, j, k) along
  // each axis (the (2R + 1)³ around it, itself included) has its bit set; R ≤ reach.
  template <int R>
  uint64_t within() const {
    static_assert(R >= 1 && R <= reach, "the halo holds `reach` nodes a side");
    uint64_t out = 0;
    for (int i = 0; i < bw; ++i) {
      uint64_t lines = 0;
      for (int x = -R; x <= R; ++x) lines |= line(i + reach + x);
      uint64_t across = 0;  // byte hj: rows hj … hj + 2R
      for (int y = 0; y <= 2 * R; ++y) across |= lines >> (8 * y);
      for (int j = 0; j < bw; ++j) {
        const unsigned rows = unsigned(across >> (8 * (j + reach - R))) & 255u;  // y = −R … R around j
        unsigned bits = 0;
        for (int z = 0; z <= 2 * R; ++z) bits |= rows >> (reach - R + z);
        out |= uint64_t(bits & 15u) << ((i * bw + j) * bw);
      }
    }
    return out;
  }
};
inline void load_mask_halo(const DdmpNodalValues& nv, size_t b, const std::vector<uint64_t>& mask, MaskHalo& halo) {
  static_assert(reach == 2 && bw == 4, "the row assembly takes 2 + 4 + 2 nodes per axis");
  const auto& nb = nv.neighbours[b];
  uint64_t around[27];  // the masks of the 27 blocks around, in neighbour_index order (z fastest)
  for (size_t q = 0; q < 27; ++q) around[q] = nb[q] < 0 ? 0 : mask[size_t(nb[q])];
  for (int hi = 0; hi < MaskHalo::width; ++hi)
    for (int hj = 0; hj < MaskHalo::width; ++hj) {
      const int dx = hi < reach ? -1 : hi < reach + bw ? 0 : 1, dy = hj < reach ? -1 : hj < reach + bw ? 0 : 1;
      const int base = (((hi + reach) & 3) * bw + ((hj + reach) & 3)) * bw;  // the row's first bit in its block
      const uint64_t* column = around + neighbour_index(dx, dy, -1);        // below, at, above
      halo.row[hi][hj] =
          uint8_t(((column[0] >> (base + 2)) & 3) | (((column[1] >> base) & 15) << 2) | (((column[2] >> base) & 3) << 6));
    }
}

// Calls fn(n) for the nodes n of a block whose bit is set in `mask`, in node order.
template <class Fn>
void for_each_bit(uint64_t mask, Fn&& fn) {
  while (mask) {
    fn(__builtin_ctzll(mask));
    mask &= mask - 1;
  }
}
// Asks for the distributions of a block's nodes in `mask` to be brought into the cache, all
// at once, before they are used one by one: they lie scattered in the memo, and waiting
// for each in turn was a fifth of the read-back's time at paper size (perf, T2P20-E8,
// 2026-11-28). The header and the first coefficients (two lines); the rest streams.
inline void prefetch_distributions(const DdmpNodalValues& nv, size_t b, uint64_t mask) {
  const DdmpDistribution* const* distribution = nv.distributions.data() + b * SparseGrid::nodes_per_block;
  for_each_bit(mask, [&](int n) {
    if (!distribution[n]) return;
    for (int line = 0; line < block_prefetched_lines; ++line)
      __builtin_prefetch(reinterpret_cast<const char*>(distribution[n]) + 64 * line);
  });
}
// Blocks in tiles of 3×3×3: a block's tile, its colour among the tiles (the parity of the
// tile's coordinates: tiles of one colour are two tiles, 24 nodes, apart along some axis),
// and the block's place in its tile (its coordinates mod 3: the 27 blocks around any block
// have 27 different places).
struct BlockTile {
  SparseGrid::Coord tile;
  int colour, place;
};
inline BlockTile block_tile(const SparseGrid::Coord& c) {
  BlockTile t;
  for (int a = 0; a < 3; ++a) t.tile[size_t(a)] = floor_div(c[size_t(a)], 3);
  t.colour = ((t.tile[0] & 1) * 2 + (t.tile[1] & 1)) * 2 + (t.tile[2] & 1);
  const auto mod3 = [](int v) { return v - 3 * floor_div(v, 3); };
  t.place = (mod3(c[0]) * 3 + mod3(c[1])) * 3 + mod3(c[2]);
  return t;
}
}  // namespace ddmp_grid_detail

// Finds the nodes that hand on their lanes — mass below `small_mass` and not held by a body
// (lane::constraint), or held with no mass at all; a node with mass within one cell (else
// neither their force nor their velocity enters anything), sizeable nodes (mass ≥
// small_mass) among its 124 neighbours (neighbour_offsets) — and their distribution
// coefficients C_li = w(d) (c₀ + c · d), d = i − l in cells over those sizeable nodes i,
// w(d) = 2^(−|d|₁): the weighted least-squares fit of a linear field, so that
// Σ_i C_li = 1 and Σ_i C_li x_i = x_l — a node outside a free surface reads back the linear
// extrapolation of the material's velocity, which keeps Eq. 8's exactness for linear fields
// in L. Where the sizeable nodes do not span 3D (a plate one node thick), or where the node
// has mass of its own and the fit would give a neighbour a negative share of it,
// C_li = w(d) / Σ w: their weighted mean.
// The work follows the surface, not the grid: a pass over the nodes makes three 64-bit masks
// per block (sizeable, with mass, handing on); only blocks with a node that may hand on look
// at their neighbourhood, through rows of those bits.
inline void find_ddmp_small_mass_nodes(const SparseGrid& grid, Real small_mass, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  // The previous step's pointers into the memo (nv.distributions) are all replaced below.
  if (distribution_memo().size() > distribution_memo_limit) clear_distribution_memo();
  const size_t blocks = grid.block_count();
  const uint64_t generation = distribution_memo_generation().load(std::memory_order_relaxed);
  DdmpNodalValues::LastFind& last = nv.last_find;
  // The last find's decisions stand where nothing they depend on changed: the same blocks, the
  // same memo (its pointers), the same threshold, and per block the masks of the 27 around.
  const bool reusable = last.layout == grid.layout() && last.generation == generation && last.small_mass == small_mass;
  std::vector<uint64_t>& sizeable = nv.sizeable_mask;  // the last find's until overwritten below
  std::vector<uint64_t>& with_mass = nv.mass_mask;
  sizeable.resize(blocks);
  with_mass.resize(blocks);
  last.candidates.resize(blocks);
  last.changed.resize(blocks);
  nv.handing.assign(blocks, 0);
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    const Real* block = grid.block(b);
    uint64_t big = 0, positive = 0, candidates = 0;
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
      const Real m = block[n * lane::count + lane::mass];
      // A node hands on when its mass is small and no body holds it, or when a body holds it
      // but no deformable point gives it mass (a node inside a rigid plate of points, one
      // cell beyond the material: docs/solver.md, "Held nodes without mass").
      const bool hands_on = m < small_mass && (block[n * lane::count + lane::constraint] == 0 || m == 0);
      big |= uint64_t(m >= small_mass) << n;
      positive |= uint64_t(m > 0) << n;
      candidates |= uint64_t(hands_on) << n;
    }
    last.changed[b] = reusable ? (big ^ sizeable[b]) | (positive ^ with_mass[b]) | (candidates ^ last.candidates[b])
                               : ~uint64_t(0);
    sizeable[b] = big;
    with_mass[b] = positive;
    last.candidates[b] = candidates;
    nv.handing[b] = candidates;
  });
  // A node keeps its distribution from step to step while its pattern stays (most do): the
  // pointers of nv.distributions stay valid until the memo is emptied.
  if (nv.distribution_generation != generation) {
    std::fill(nv.distributions.begin(), nv.distributions.end(), nullptr);
    nv.distribution_generation = generation;
  }
  // Whether a mask of the 27 blocks around b (b among them) changed since the last find.
  const auto neighbourhood_changed = [&](size_t b) {
    for (const int nb : nv.neighbours[b])
      if (nb >= 0 && last.changed[size_t(nb)]) return true;
    return false;
  };
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    uint64_t candidates = nv.handing[b];
    if (!candidates) return;
    // Unchanged around: the same patterns, so the same nodes hand on with the same
    // distributions, which nv.distributions still holds (2026-11-29: 4 % of a QUICK lattice's
    // DDMP step went to finding them again).
    if (reusable && !neighbourhood_changed(b)) {
      nv.handing[b] = last.handing[b];
      return;
    }
    // The same node by node: a node's decision and pattern depend on the masks within
    // `reach` nodes of it (and its own candidacy), so only nodes that near a changed bit
    // are looked at again. A block is 4 nodes wide and a change reaches 2 into it, so
    // most nodes of a changed block's 26 neighbours keep theirs. perf, 2026-11-29: the find
    // 3.67 → 3.26 % of the first 400 DDMP steps of the paper-size T1P30 impact, 3.56 → 3.06 %
    // of the QUICK T2P30 lattice's whole run (its second pass 1.69 → 1.24 %); bit-identical.
    uint64_t kept = 0;
    if (reusable) {
      MaskHalo changed;
      load_mask_halo(nv, b, last.changed, changed);
      const uint64_t again = changed.within<reach>();
      kept = last.handing[b] & ~again;
      candidates &= again;
    }
    nv.handing[b] = kept;
    if (!candidates) return;
    MaskHalo positive;
    load_mask_halo(nv, b, with_mass, positive);
    candidates &= positive.within<1>();  // a node with mass within one cell: its L or force matters
    if (!candidates) return;
    prefetch_distributions(nv, b, candidates);  // the last step's, compared below
    MaskHalo big;
    load_mask_halo(nv, b, sizeable, big);
    uint64_t handing = 0;
    int column_of = -1;
    std::array<uint64_t, NeighbourPattern::words> column{};
    const DdmpDistribution* last = nullptr;
    for_each_bit(candidates, [&](int n) {
      const int i = n >> 4, j = (n >> 2) & 3, k = n & 3;
      if (n >> 2 != column_of) column = big.columns(i, j), column_of = n >> 2;
      NeighbourPattern pattern;
      for (int w = 0; w < NeighbourPattern::words; ++w) pattern.bits[size_t(w)] = (column[size_t(w)] >> k) & 0x1F1F'1F1F'1F1F'1F1Full;
      // The node's own bit in `big` is clear (a candidate is not sizeable): it marks own mass.
      if ((positive.row[i + reach][j + reach] >> (k + reach)) & 1) pattern.set(own_mass_bit);
      // The node's distribution of the last step, else the last node's (neighbours along a
      // face share their pattern), else the memo's.
      const DdmpDistribution*& d = nv.distributions[b * SparseGrid::nodes_per_block + size_t(n)];
      if (!(d && d->pattern == pattern)) d = last && last->pattern == pattern ? last : &remembered_distribution(pattern);
      last = d;
      if (d->hands_on()) handing |= uint64_t(1) << n;
    });
    nv.handing[b] = kept | handing;
  });
  // The hand-on's order below depends only on which blocks have nodes handing on.
  bool same_blocks = reusable;
  for (size_t b = 0; same_blocks && b < blocks; ++b) same_blocks = (nv.handing[b] != 0) == (last.handing[b] != 0);
  last.handing = nv.handing;
  last.layout = grid.layout();
  last.generation = generation;
  last.small_mass = small_mass;
  nv.mass_mask_current = true;
  if (same_blocks) return;
  // The blocks with nodes handing on, by tile colour, tile and place in the tile: the
  // hand-on's order (move_ddmp_small_mass_lanes).
  struct Entry {
    SparseGrid::Coord tile;
    int place;
    uint32_t block;
  };
  thread_local std::array<std::vector<Entry>, 8> by_colour;  // kept: no allocation a step
  for (auto& list : by_colour) list.clear();
  for (size_t b = 0; b < blocks; ++b)
    if (nv.handing[b]) {
      const BlockTile t = block_tile(grid.coord(b));
      by_colour[size_t(t.colour)].push_back({t.tile, t.place, uint32_t(b)});
    }
  for (size_t colour = 0; colour < by_colour.size(); ++colour) {
    auto& list = by_colour[colour];
    std::sort(list.begin(), list.end(), [](const Entry& x, const Entry& y) {
      return x.tile != y.tile ? x.tile < y.tile : x.place < y.place;
    });
    auto& order = nv.handing_blocks[colour];
    auto& begin = nv.handing_tile_begin[colour];
    order.clear();
    begin.clear();
    for (size_t e = 0; e < list.size(); ++e) {
      if (e == 0 || list[e].tile != list[e - 1].tile) begin.push_back(uint32_t(e));
      order.push_back(list[e].block);
    }
    begin.push_back(uint32_t(list.size()));
  }
}

// Hands lanes [First, First + Count) of every small-mass node on to its sizeable
// neighbours, C_li times each, and zeroes them (mass, momentum and force after P2G; the
// remapped momentum of MUSL). Each source pushes its shares; a source reaches the blocks
// next to its own (reach 2 < 4 nodes), so the tiles of 3×3×3 blocks of one tile colour
// write disjoint nodes and run in parallel, each tile's blocks in turn, and a receiving
// node gets its parts in a fixed order (tile colour, tile, block, source node, share): the
// same sums on any thread count. A tile's 27 blocks one after the other keep the nodes they
// write in cache (27 sweeps over the grid, one per block colour, did not at paper size).
template <int First, int Count>
void move_ddmp_small_mass_lanes(SparseGrid& grid, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  // The source's lanes in their places of a node, the others zero; only its non-zero lanes
  // of [First, First + Count) change in a receiver (one masked multiply-add a share,
  // num::MaskedLanes; a zero would add nothing): most sources lie outside the material,
  // with force but no mass or momentum, and push half a node. Sources never receive (they
  // are not sizeable), so each is read and cleared as it is pushed.
  Real* nodes = grid.block(0);
  const auto hand_on_block = [&](size_t b) {
    BlockNodeIndex index;
    load_block_node_index(nv, b, index);
    for_each_bit(nv.handing[b], [&](int n) {
      const DdmpDistribution& d = *nv.distributions[b * SparseGrid::nodes_per_block + size_t(n)];
      Real* node = grid.block(b) + n * lane::count;
      Pack source{};
      unsigned moved = 0;
      for (int c = First; c < First + Count; ++c) {
        source[c] = node[c], node[c] = 0;
        moved |= unsigned(source[c] != 0) << c;
      }
      const num::MaskedLanes pushed(source, moved);
      const auto push = [&](auto halves) __attribute__((always_inline)) {
        for_each_share(d, index, n, [&](size_t receiver, Real C) {
          pushed.template add_into<decltype(halves)::value>(nodes + receiver * lane::count, C);
        });
      };
      switch (pushed.halves()) {
        case num::both_halves: push(std::integral_constant<unsigned, num::both_halves>{}); break;
        case num::high_lanes: push(std::integral_constant<unsigned, num::high_lanes>{}); break;
        case num::low_lanes: push(std::integral_constant<unsigned, num::low_lanes>{}); break;
        default: break;  // nothing to push
      }
    });
  };
  for (size_t colour = 0; colour < nv.handing_blocks.size(); ++colour) {
    const auto& order = nv.handing_blocks[colour];
    const auto& tile_begin = nv.handing_tile_begin[colour];
    if (order.empty()) continue;
    tbb::parallel_for(size_t(0), tile_begin.size() - 1, [&](size_t tile) {
      // Each block's distributions asked for one block ahead, so that their misses overlap
      // the block before (prefetch_distributions): the hand-on 6–11 % faster at paper size
      // (perf, two builds side by side, both orders; the read-back measured no gain from it).
      const auto prefetch = [&](uint32_t e) { prefetch_distributions(nv, order[e], nv.handing[order[e]]); };
      const uint32_t first = tile_begin[tile], end = tile_begin[tile + 1];
      prefetch(first);
      for (uint32_t e = first; e < end; ++e) {
        if (e + 1 < end) prefetch(e + 1);
        hand_on_block(order[e]);
      }
    });
  }
}

// Lanes [First, First + Count) of every small-mass node from its sizeable neighbours,
// v_l = Σ_i C_li v_i (the new velocity and its change after the grid update; MUSL's
// remapped velocity). A node without mass (most: outside the material) has no point with a
// weight on it (the points' weights S_ip made its mass), so of these lanes only its velocity
// — the first three, read by the gradient L through ∇S — reaches the points: the others keep
// what the grid update left there.
template <int First, int Count>
void spread_ddmp_small_mass_lanes(SparseGrid& grid, DdmpNodalValues& nv) {
  using namespace ddmp_grid_detail;
  constexpr int massless_count = Count < 3 ? Count : 3;
  // Whole nodes (or the halves holding the lanes) summed, one multiply-add a share
  // (num::NodeSum); the lanes kept. The sums read sizeable nodes only, so each is written
  // straight back.
  const Real* nodes = grid.block(0);
  tbb::parallel_for(size_t(0), grid.block_count(), [&](size_t b) {
    if (!nv.handing[b]) return;
    BlockNodeIndex index;
    load_block_node_index(nv, b, index);
    const DdmpDistribution* const* distribution = nv.distributions.data() + b * SparseGrid::nodes_per_block;
    Real* block = grid.block(b);
    const auto read_back = [&](uint64_t mask, auto halves, auto count) __attribute__((always_inline)) {
      constexpr unsigned H = decltype(halves)::value;
      constexpr int lanes = decltype(count)::value;
      for_each_share_pair(
          mask, distribution, index,
          [&](num::NodeSum& sum, size_t receiver, Real C) { sum.template add<H>(C, nodes + receiver * lane::count); },
          [&](int n, const num::NodeSum& sum) {
            Real* node = block + n * lane::count;
            for (int c = First; c < First + lanes; ++c) node[c] = sum[c];
          });
    };
    prefetch_distributions(nv, b, nv.handing[b]);
    read_back(nv.handing[b] & nv.mass_mask[b], std::integral_constant<unsigned, halves_of(First, Count)>{},
              std::integral_constant<int, Count>{});
    read_back(nv.handing[b] & ~nv.mass_mask[b], std::integral_constant<unsigned, halves_of(First, massless_count)>{},
              std::integral_constant<int, massless_count>{});
  });
}

}  // namespace latmpm::mpm
