// One penalty-contact point's force on its way to the grid (step_stages.hpp,
// add_contact_forces): the point's place in the one-process particle order, the body it
// touches, the force, its energy terms and the weights that spread it to the nodes. On
// several MPI processes every process receives every touching point's record
// (Domain::contact_spreads_in_order) and adds them, in the one-process order, to the nodes
// it holds, and forms the chunked reaction sums in that order (contact_sums_in_order): the
// one-process bits (docs/cluster.md, "Penalty contact"). Plain values: sent as bytes.
#pragma once
#include <cstdint>
#include <type_traits>

#include "mpm/real.hpp"

namespace latmpm::mpm {

struct ContactSpread {
  static constexpr int max_nodes_per_axis = 4;  // B-spline 3, CPDI1, cpGIMP
  uint64_t index = 0;  // the point's place in the one-process particle order (a local index until ordered)
  int32_t body = -1;   // the penalty rigid body it touches
  int32_t nodes = 0;   // nodes per axis of its weights
  int32_t base[3] = {0, 0, 0};
  Real force[3] = {0, 0, 0};
  Real spring_energy = 0, friction_work = 0;
  // S_I of node base + (i, j, k) at (i·nodes + j)·nodes + k; zero: the node is not touched.
  Real weight[max_nodes_per_axis * max_nodes_per_axis * max_nodes_per_axis] = {};
};
static_assert(std::is_trivially_copyable_v<ContactSpread>);

}  // namespace latmpm::mpm
