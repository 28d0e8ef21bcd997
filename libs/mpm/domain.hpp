// The seam where a run spread over several processes plugs in (the MPI issue, docs/
// cluster.md): what a step needs from the other parts of the domain, and nothing else. The
// physics never talks to other processes itself; the step calls these at fixed points:
//
//   migrate_particles  before a sort: particles that left this process's buckets handed on
//                      (the sort itself happens on every process at the same step).
//   share_grid         after the active blocks are set: which nodes this process shares
//                      with which others.
//   exchange_halo      after each colour of a scatter: the shared nodes that this colour's
//                      buckets added to made whole on every process that holds them, so
//                      node sums are added in the one-process order (mass, momentum,
//                      force, constraint markers; Cabana's halo "scatter" in colour steps).
//   sum_in_order       sums of per-bucket and per-block partial sums (energies, reactions,
//                      body centres, the record layer) in the one-process order of the
//                      buckets and blocks, so they too are bit-identical to one process.
//   bucket_placement   a checkpoint: where this process's buckets go in the one-process
//                      layout, so that every process writes its own rows of the file one
//                      process writes (write_shared_rows).
//   distribute_buckets a restored checkpoint (every process read all of it): each keeps
//                      its share of the buckets as they are, so it resumes on any count.
//   particles_in_id_block  a snapshot: the particles of a block of point ids, so that each
//                      process writes its block of the file's rows (points in id order).
//   write_shared_rows  an output file one process laid out, every process writing its rows
//                      into it at once (parallel HDF5).
//   contact_spreads_in_order  penalty contact: every touching point's force record, in the
//                      one-process particle order, on every process (contact_spread.hpp).
//   reduce_sum/max/min the other global sums and extremes (speeds for the stable time
//                      step, rigid couplings and contact, carried energies).
//   text_of_largest    the words of the process holding the domain's extreme (the
//                      fastest particle a stop names).
//
// For one process each does nothing, and a run's results do not depend on it. The MPI
// domain (mpi_domain.hpp, a build with -DLATMPM_MPI=ON) keeps the particles' state
// bit-identical to one process (docs/architecture.md, "The domain seam").
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/hdf5_file.hpp"
#include "mpm/bucket_layout.hpp"
#include "mpm/contact_spread.hpp"
#include "mpm/particle_buckets.hpp"
#include "mpm/particle_fields.hpp"
#include "mpm/particles.hpp"
#include "mpm/real.hpp"

namespace latmpm::mpm {

class SparseGrid;
class ParticleBuckets;
struct Settings;

// Column sums of `rows` (`width` values per item, items in the order of their keys) added
// item by item from zero: how one process adds per-bucket and per-block partial sums.
inline std::vector<Real> sum_rows(const std::vector<Real>& rows, size_t width) {
  std::vector<Real> sum(width, Real(0));
  for (size_t i = 0; i + width <= rows.size(); i += width)
    for (size_t c = 0; c < width; ++c) sum[c] += rows[i + c];
  return sum;
}

// What a process sent to the others since the start (docs/cluster.md's halo volume).
struct DomainTraffic {
  uint64_t halo_nodes = 0;      // shared nodes sent in halo exchanges (8 lanes of 8 bytes each)
  uint64_t halo_bytes = 0;      // their lanes and the shared nodes' coordinates
  uint64_t migration_bytes = 0;
  uint64_t particles_sent = 0;  // migrated to another process
};

class SingleProcessDomain {
 public:
  void check_supported(const Settings&, const std::string&) const {}
  void migrate_particles(Particles&, Real) {}
  void share_grid(const SparseGrid&, const ParticleBuckets&) {}
  void exchange_halo(SparseGrid&, int) {}
  Real reduce_sum(Real local) const { return local; }
  Vec3 reduce_sum(const Vec3& local) const { return local; }
  // Sums of partial sums in their one-process order: `rows` holds `width` values per item
  // (a bucket, a grid block) of this process, items in ascending `keys`; the column sums
  // over every process's items, added in key order (sum_rows), the same bits as one
  // process. A key several processes hold (a grid block on a partition border, whose
  // nodes the halo made the same everywhere) counts once.
  std::vector<Real> sum_in_order(const std::vector<uint64_t>&, const std::vector<Real>& rows, size_t width) const {
    return sum_rows(rows, width);
  }
  // The same for a sum that one process runs on from item to item across buckets (a sum
  // over particles in their order): `rows` holds the items of bucket g after those of
  // bucket g − 1, `counts[g]` of them, the buckets in ascending `keys`.
  std::vector<Real> sum_in_sequence(const std::vector<uint64_t>&, const std::vector<uint32_t>&,
                                    const std::vector<Real>& rows, size_t width) const {
    return sum_rows(rows, width);
  }
  Real reduce_max(Real local) const { return local; }
  Real reduce_min(Real local) const { return local; }
  // The `text` of the process whose `value` is the largest (the lowest rank of equals), on
  // every process: a message naming one particle of the whole domain. Collective.
  std::string text_of_largest(double, const std::string& text) const { return text; }
  DomainTraffic traffic() const { return {}; }
  // Returns once every process has called it (one process: at once).
  void barrier() const {}
  int process_count() const { return 1; }
  int rank() const { return 0; }
  // Where this process's buckets go in the one-process layout (bucket_layout.hpp); `particles`
  // held here. Collective.
  BucketPlacement bucket_placement(const ParticleBuckets& buckets, size_t particles) const {
    return place_buckets(bucket_sizes(buckets.buckets()), buckets.buckets(), particles);
  }
  // Which fields of the registry (particle_fields.hpp, in its order) the run carries: an
  // optional field held by any process. Collective.
  std::vector<uint8_t> fields_present(const Particles& particles) const {
    std::vector<uint8_t> present;
    for_each_particle_field(particles, [&](const ParticleField& f, const auto& v, const auto&) {
      present.push_back(!(f.optional && v.empty()));
    });
    return present;
  }
  // The particles whose ids are this process's block [first, first + count) of an even cut of
  // 0 .. total − 1 among the processes (one process: all of them); sets `first`. Collective.
  Particles particles_in_id_block(const Particles& local, size_t, size_t& first) const {
    first = 0;
    return local;
  }
  // The file at `path` (rank 0's path; the others' is ignored), which rank 0 laid out and
  // closed, opened on every process; fill(file) writes this process's rows into it
  // (Hdf5File::write_rows, every process the same datasets in the same order), and the file
  // is closed. Collective: several processes write one file at once (parallel HDF5).
  void write_shared_rows(const std::string& path, const std::function<void(Hdf5File&)>& fill) const {
    Hdf5File file(path, Hdf5File::Mode::read_write);
    fill(file);
    file.close();
  }
  // After every process read the whole state (a checkpoint): keeps this process's buckets
  // and their particles, in their order.
  void distribute_buckets(Particles&, BucketTables&) {}
  // Every process's records (`mine`: index = the point's index here, in ascending order),
  // their index made the one-process one, in that order. Collective.
  std::vector<ContactSpread> contact_spreads_in_order(std::vector<ContactSpread> mine, const ParticleBuckets&) const {
    return mine;
  }
};

}  // namespace latmpm::mpm

#ifdef LATMPM_WITH_MPI
namespace latmpm::mpm {
class MpiDomain;
using Domain = MpiDomain;
}  // namespace latmpm::mpm
#include "mpm/mpi_domain.hpp"
#else
namespace latmpm::mpm {
// The domain a Simulation runs on; the MPI build chooses MpiDomain.
using Domain = SingleProcessDomain;
}  // namespace latmpm::mpm
#endif
