// The seam where a run spread over several processes will plug in (the MPI issue): what a
// step needs from the other parts of the domain, and nothing else. The physics never talks
// to other processes itself; the step calls these three at fixed points:
//
//   exchange_halo      after P2G: nodal sums of the blocks this process shares with its
//                      neighbours added up (mass, momentum, force, constraint markers), so
//                      the grid update sees whole nodes (Cabana's halo "scatter").
//   reduce_sum/max/min the step's global sums (energies, speeds for the stable time step,
//                      reactions of the node update, rigid couplings and contact, body
//                      centres) over all processes.
//   migrate_particles  before a sort: particles that left this process's part handed on.
//
// For one process each does nothing, and a run's results do not depend on it. An MPI domain
// must keep results bit-identical to one process (sums in a fixed order), as the thread
// count does now (docs/architecture.md, "The domain seam").
#pragma once
#include "mpm/real.hpp"

namespace latmpm::mpm {

class SparseGrid;
struct Particles;

class SingleProcessDomain {
 public:
  void exchange_halo(SparseGrid&) const {}
  Real reduce_sum(Real local) const { return local; }
  Vec3 reduce_sum(const Vec3& local) const { return local; }
  Real reduce_max(Real local) const { return local; }
  Real reduce_min(Real local) const { return local; }
  void migrate_particles(Particles&) const {}
  int process_count() const { return 1; }
};

// The domain a Simulation runs on; an MPI build will choose another type here.
using Domain = SingleProcessDomain;

}  // namespace latmpm::mpm
