// The grid nodes of fixed point bodies, found once (issue 14: "model only what the scene
// requires"). A fixed body's points never move and carry no mass to the grid: all they do in
// a step is mark the nodes their stencils reach with the body's constraint (transfer.hpp).
// Those nodes do not change, so the step leaves the points out of its transfers and writes
// the marks from this list after each grid clear instead. The printed base plate under paper
// A's impact lattice, a fixed body, is 30 % of its points (docs/tradeoff.md, "Fixed bodies
// marked once").
//
// The same nodes, the same marks: the list is built with the weights the scatter uses (the
// shape's own stencil, DDMP's linear corner weights) and a node is marked where the product
// of its three weights is positive, as scatter_bucket does; the mark is the largest body
// index + 1 of the bodies touching the node, as the scatter's max gives. Marks on blocks no
// moving point reaches are dropped: those nodes get no mass, momentum or force, so their
// constraint changes nothing. Results are bit-identical to the points scattered every step
// (test_mpm "Fixed bodies marked once*").
//
// Not used (the points stay in the step) with several processes (a node a process holds
// may be reached only by another's fixed points), with grid contact's fields, and with CPDI1
// (whose stencils are its domain's).
#pragma once
#include <algorithm>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "mpm/particles.hpp"
#include "mpm/shape_linear.hpp"
#include "mpm/sparse_grid.hpp"
#include "mpm/stencil.hpp"
#include "mpm/transfer.hpp"

namespace latmpm::mpm {

struct FixedBodyNodes {
  struct Block {
    SparseGrid::Coord coord;                    // block coordinates
    std::vector<std::pair<int, Real>> marks;    // node offset in the block (Reals), marker
  };
  std::vector<Block> blocks;  // in block-key order
  bool ready = false;         // built for the particles' current positions
};

// The nodes the points of bodies with BodyInfo::marked_once reach, with their markers.
template <class Shape>
FixedBodyNodes find_fixed_body_nodes(const Particles& ps, const std::vector<BodyInfo>& bodies, Real h) {
  // The weights the scatter marks with: DDMP's are the linear hat's (shape_ddmp.hpp).
  using Weights = std::conditional_t<Shape::smoothed_gradient, LinearShape, Shape>;
  constexpr int N = Weights::nodes_per_axis;
  constexpr int bw = SparseGrid::block_width;
  std::vector<std::tuple<uint64_t, int, Real>> marks;  // block key, node offset, marker
  for (size_t p = 0; p < ps.size(); ++p) {
    const int32_t body = ps.body[p];
    if (!bodies[size_t(body)].marked_once) continue;
    const Real marker = Real(body + 1);
    const auto st = make_stencil<Weights>(ps.position[p], stencil_half_size<Weights>(ps, p, h), 1 / h);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        for (int k = 0; k < N; ++k) {
          if (!(st.w[i][0] * st.w[j][1] * st.w[k][2] > 0)) continue;
          const int n[3] = {st.base[0] + i, st.base[1] + j, st.base[2] + k};
          const int b[3] = {floor_div(n[0], bw), floor_div(n[1], bw), floor_div(n[2], bw)};
          marks.emplace_back(SparseGrid::block_key(b[0], b[1], b[2]),
                             SparseGrid::node_offset(n[0] - bw * b[0], n[1] - bw * b[1], n[2] - bw * b[2]), marker);
        }
  }
  // Sorted by node, then marker: a node's last entry holds its largest marker.
  std::sort(marks.begin(), marks.end());
  FixedBodyNodes out;
  for (size_t e = 0; e < marks.size(); ++e) {
    const auto& [key, offset, marker] = marks[e];
    if (e + 1 < marks.size() && std::get<0>(marks[e + 1]) == key && std::get<1>(marks[e + 1]) == offset) continue;
    if (out.blocks.empty() || SparseGrid::block_key(out.blocks.back().coord[0], out.blocks.back().coord[1],
                                                    out.blocks.back().coord[2]) != key)
      out.blocks.push_back({SparseGrid::key_to_coord(key), {}});
    out.blocks.back().marks.emplace_back(offset, marker);
  }
  out.ready = true;
  return out;
}

// The fixed bodies' points as the step left them before they were taken out of it: at their
// body's velocity (zero), their positions + 0 (so a −0 coordinate reads +0). A caller may have
// set other values through Simulation::mutable_particles(); the gather no longer resets them.
inline void rest_fixed_body_points(Particles& ps, const std::vector<BodyInfo>& bodies) {
  for (size_t p = 0; p < ps.size(); ++p) {
    const BodyInfo& body = bodies[size_t(ps.body[p])];
    if (!body.marked_once) continue;
    ps.velocity[p] = body.velocity.template cast<ParticleReal>();
    ps.position[p] += Vec3::Zero();
  }
}

// Writes the marks into the constraint lane of the active grid (after it was cleared). Serial:
// a paper-size base plate's list is ~1,500 blocks, far below a step's other passes.
inline void mark_fixed_body_nodes(const FixedBodyNodes& nodes, SparseGrid& grid) {
  for (const FixedBodyNodes::Block& b : nodes.blocks) {
    const int index = grid.find(b.coord[0], b.coord[1], b.coord[2]);
    if (index < 0) continue;  // no moving point reaches it this step
    Real* block = grid.block(size_t(index));
    for (const auto& [offset, marker] : b.marks)
      block[offset + lane::constraint] = std::max(block[offset + lane::constraint], marker);
  }
}

// After each grid clear: the marks, from the list (made, and the points set to rest, the first
// time after the list went stale). Nothing without a marked-once body; CPDI1 never has one.
template <class Shape>
void mark_fixed_bodies(FixedBodyNodes& nodes, Particles& ps, const std::vector<BodyInfo>& bodies, Real h,
                       SparseGrid& grid) {
  if constexpr (!Shape::uses_domain_vertices) {  // CPDI1 keeps its points in the step (simulation.cpp)
    if (std::none_of(bodies.begin(), bodies.end(), [](const BodyInfo& b) { return b.marked_once; })) return;
    if (!nodes.ready) {
      nodes = find_fixed_body_nodes<Shape>(ps, bodies, h);
      rest_fixed_body_points(ps, bodies);
    }
    mark_fixed_body_nodes(nodes, grid);
  }
}

}  // namespace latmpm::mpm
