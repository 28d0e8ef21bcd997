// The domain of a run on several MPI processes (domain.hpp's seam; docs/cluster.md). Each
// process holds whole particle buckets, a contiguous piece of their Morton curve weighted by
// particle count (bucket_partition.hpp), and the grid blocks its buckets' stencils reach.
// Nodes reached from buckets of several processes are kept whole on each of them by the
// halo exchange after every colour of a scatter: the one-process scatter adds bucket
// buffers colour by colour, so the process whose bucket of that colour touches a shared
// node sends the node's new lanes to the others, which take them as they are. The node sums
// are thus added in the one-process order, and the particles' state stays bit-identical
// to one process for any process count. Partial sums per bucket and per block are summed
// in the one-process order of their keys (sum_in_order), the other sums in rank order:
// the same bits on every process, so every process takes the same time step.
//
// Before the first sort every process holds every particle (each built the Simulation from
// the whole scene): reductions then return the local value, which is the global one, and
// the first migration keeps only the process's own buckets.
//
// Calls MPI from the thread that runs the step, never from two threads at once
// (MPI_THREAD_SERIALIZED, which MpiSession asks for: tbb::task_arena::execute may run the
// step on a worker thread).
// Without MPI initialised (a test program of the MPI build), it is one process.
#pragma once
#include <mpi.h>

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mpm/bucket_partition.hpp"
#include "mpm/contact_spread.hpp"
#include "mpm/domain.hpp"
#include "mpm/particles.hpp"
#include "mpm/real.hpp"

namespace latmpm::mpm {

class SparseGrid;
class ParticleBuckets;
struct Settings;

// MPI for the life of a program: MPI_Init_thread (serialized) at construction, MPI_Finalize
// at finish(0), MPI_Abort for a non-zero exit status so that no process waits for one that
// has stopped. Runs with `mpirun -np N program ...`; a single process without mpirun too.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int finish(int exit_status);
  int rank() const { return rank_; }

 private:
  int rank_ = 0;
  bool finished_ = false;
};

class MpiDomain {
 public:
  // On `communicator` (MPI_COMM_WORLD unless MpiDomain::default_communicator was set).
  MpiDomain();
  explicit MpiDomain(MPI_Comm communicator);

  // InputError for what does not run on several processes: DDMP (its node passes reach
  // beyond a node), grid contact (its normals read neighbours' masses), the null-space filter
  // (one solve over a whole body).
  void check_supported(const Settings& settings, const std::string& where) const;
  void migrate_particles(Particles& particles, Real cell_size);
  void share_grid(const SparseGrid& grid, const ParticleBuckets& buckets);
  void exchange_halo(SparseGrid& grid, int colour);
  Real reduce_sum(Real local) const;
  Vec3 reduce_sum(const Vec3& local) const;
  std::vector<Real> sum_in_order(const std::vector<uint64_t>& keys, const std::vector<Real>& rows, size_t width) const;
  std::vector<Real> sum_in_sequence(const std::vector<uint64_t>& keys, const std::vector<uint32_t>& counts,
                                    const std::vector<Real>& rows, size_t width) const;
  Real reduce_max(Real local) const;
  void barrier() const;
  Real reduce_min(Real local) const;
  std::string text_of_largest(double value, const std::string& text) const;
  int process_count() const { return size_; }
  int rank() const { return rank_; }
  BucketPlacement bucket_placement(const ParticleBuckets& buckets, size_t particles) const;
  // Which particle fields the run carries (particle_fields.hpp's order), the same on every
  // process (collective): optional fields are empty where a process holds no particle.
  std::vector<uint8_t> fields_present(const Particles& particles) const;
  Particles particles_in_id_block(const Particles& local, size_t total, size_t& first) const;
  void write_shared_rows(const std::string& path, const std::function<void(Hdf5File&)>& fill) const;
  void distribute_buckets(Particles& particles, BucketTables& tables);
  std::vector<ContactSpread> contact_spreads_in_order(std::vector<ContactSpread> mine,
                                                      const ParticleBuckets& buckets) const;

  const BucketPartition& partition() const { return partition_; }
  const DomainTraffic& traffic() const { return traffic_; }
  // For tests: the communicator of domains made from now on (MPI_COMM_WORLD by default).
  static void set_default_communicator(MPI_Comm communicator);

 private:
  bool distributed() const { return size_ > 1 && distributed_; }
  void repartition(const Particles& particles, Real inv_h);
  // Sends each particle p whose owner[p] is another process to it (the fields of `present`,
  // packed); what the others sent here comes back packed, in rank order. Collective.
  struct SentParticles {
    std::vector<char> received;
    uint64_t bytes = 0, particles = 0;  // sent
  };
  SentParticles send_to_owners(const Particles& particles, const std::vector<int>& owner,
                               const std::vector<uint8_t>& present) const;
  // Every process's bucket sizes (bucket_layout.hpp), in rank order. Collective.
  std::vector<BucketSize> all_bucket_sizes(const std::vector<Bucket>& mine) const;
  std::vector<Real> gather_in_rank_order(const Real* local, int count) const;

  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, size_ = 1;
  bool distributed_ = false;  // false until the first migration: every process holds every particle
  BucketPartition partition_;
  // Halo lists of the current grid, per colour and other process: offsets (Reals) of the
  // first lane of each node in the grid's storage, in the order both sides agree on.
  std::array<std::vector<std::vector<size_t>>, 8> send_nodes_, receive_nodes_;
  std::vector<Real> send_buffer_, receive_buffer_;
  DomainTraffic traffic_;
};

}  // namespace latmpm::mpm
