#include "mpm/mpi_domain.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>
#include <type_traits>

#include "core/errors.hpp"
#include "core/shared_hdf5_file.hpp"
#include "mpm/domain.hpp"
#include "mpm/particle_buckets.hpp"
#include "mpm/particle_fields.hpp"
#include "mpm/settings.hpp"
#include "mpm/sparse_grid.hpp"

namespace latmpm::mpm {

namespace {
MPI_Comm default_communicator = MPI_COMM_WORLD;

// Repartition when the largest process holds this much more than the mean (MPI issue point 1).
constexpr double imbalance_threshold = 1.25;

void check(int status, const char* what) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// A record of `bytes` bytes (a packed particle, a table row) as one MPI element, so that
// counts and displacements are in records: MPI's counts are ints, and an int of bytes
// overflows near 10 M particles of ~217 bytes, an int of particles at 2^31 of them.
class RecordType {
 public:
  explicit RecordType(size_t bytes) {
    if (bytes == 0 || bytes > size_t(std::numeric_limits<int>::max())) throw std::logic_error("RecordType: size");
    check(MPI_Type_contiguous(int(bytes), MPI_BYTE, &type_), "MPI_Type_contiguous");
    check(MPI_Type_commit(&type_), "MPI_Type_commit");
  }
  ~RecordType() { MPI_Type_free(&type_); }
  RecordType(const RecordType&) = delete;
  RecordType& operator=(const RecordType&) = delete;
  operator MPI_Datatype() const { return type_; }

 private:
  MPI_Datatype type_ = MPI_DATATYPE_NULL;
};

// A count of records as MPI's int, refused rather than wrapped.
int record_count(size_t records) {
  if (records > size_t(std::numeric_limits<int>::max()))
    throw std::runtime_error("MPI: " + std::to_string(records) + " records exceed an int count");
  return int(records);
}

// --- Particles as bytes: every field of the registry (particle_fields.hpp), in its order ---

// Which fields of the registry travel: `present[f]` for the f-th field visited. An optional
// field is empty on a process that holds no particle, so the mask is reduced over the
// processes (fields_present), never read from one process's arrays.
using FieldMask = std::vector<uint8_t>;

size_t particle_bytes(const Particles& ps, const FieldMask& present) {
  size_t bytes = 0, f = 0;
  for_each_particle_field(ps, [&](const ParticleField&, const auto& v, const auto&) {
    if (present[f++]) bytes += sizeof(v[0]);
  });
  return bytes;
}

void pack_particle(const Particles& ps, size_t p, char*& out, const FieldMask& present) {
  size_t f = 0;
  for_each_particle_field(ps, [&](const ParticleField&, const auto& v, const auto&) {
    if (!present[f++]) return;
    std::memcpy(out, &v[p], sizeof(v[p]));
    out += sizeof(v[p]);
  });
}

void unpack_particle(Particles& ps, const char*& in, const FieldMask& present) {
  size_t f = 0;
  for_each_particle_field(ps, [&](const ParticleField&, auto& v, const auto&) {
    if (!present[f++]) return;
    v.emplace_back();
    std::memcpy(static_cast<void*>(&v.back()), in, sizeof(v.back()));  // plain values, Eigen's too
    in += sizeof(v.back());
  });
}

// Keeps the particles whose keep[p] is set, in their order.
void keep_particles(Particles& ps, const std::vector<uint8_t>& keep) {
  for_each_particle_field(ps, [&](const ParticleField& f, auto& v, const auto&) {
    if (f.optional && v.empty()) return;
    size_t to = 0;
    for (size_t p = 0; p < keep.size(); ++p)
      if (keep[p]) v[to++] = v[p];
    v.resize(to);
  });
}

std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> d(counts.size(), 0);
  for (size_t i = 1; i < counts.size(); ++i) d[i] = d[i - 1] + counts[i - 1];
  return d;
}

// Every process's keys, one after the other in rank order; sizes and displs per process.
struct GatheredKeys {
  std::vector<uint64_t> keys;
  std::vector<int> sizes, displs;
};

GatheredKeys allgather_keys(const std::vector<uint64_t>& mine, MPI_Comm comm, int processes) {
  GatheredKeys out;
  const int n = int(mine.size());
  out.sizes.assign(size_t(processes), 0);
  check(MPI_Allgather(&n, 1, MPI_INT, out.sizes.data(), 1, MPI_INT, comm), "MPI_Allgather");
  out.displs = displacements(out.sizes);
  out.keys.resize(size_t(out.displs.back() + out.sizes.back()));
  check(MPI_Allgatherv(mine.data(), n, MPI_UINT64_T, out.keys.data(), out.sizes.data(), out.displs.data(),
                       MPI_UINT64_T, comm),
        "MPI_Allgatherv");
  return out;
}
}  // namespace

// --- MpiSession ----------------------------------------------------------------------------

MpiSession::MpiSession(int& argc, char**& argv) {
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided), "MPI_Init_thread");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
}

MpiSession::~MpiSession() {
  if (!finished_) finish(0);
}

int MpiSession::finish(int exit_status) {
  finished_ = true;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (exit_status != 0 && size > 1) {
    // The others may wait in a collective for this one: stop them all with this status.
    std::fflush(stdout);
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, exit_status);
  }
  MPI_Finalize();
  return exit_status;
}

// --- MpiDomain -----------------------------------------------------------------------------

void MpiDomain::set_default_communicator(MPI_Comm communicator) { default_communicator = communicator; }

MpiDomain::MpiDomain() : MpiDomain(default_communicator) {}

MpiDomain::MpiDomain(MPI_Comm communicator) {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  if (!initialised || finalised) return;  // one process
  comm_ = communicator;
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

void MpiDomain::check_supported(const Settings& settings, const std::string& where) const {
  if (size_ > 1 && settings.shape_function == ShapeFunctionKind::ddmp)
    throw InputError(where, "grid.shape",
                     "ddmp does not run on several MPI processes yet (its node passes reach a node's neighbours); "
                     "run it on one process");
  if (size_ > 1 && settings.field_contact.enabled)
    throw InputError(where, "contact",
                     "grid contact does not run on several MPI processes yet (its normals read the mass of a "
                     "node's neighbours, which a process holds only for its own blocks); run it on one process");
  if (size_ > 1 && settings.null_space_filter != NullSpaceFilter::none)
    throw InputError(where, "grid.null_space_filter",
                     "does not run on several MPI processes (its projection is one solve over a whole body); "
                     "run it on one process");
}

Real MpiDomain::reduce_max(Real local) const {
  if (!distributed()) return local;
  Real out = local;
  check(MPI_Allreduce(&local, &out, 1, MPI_DOUBLE, MPI_MAX, comm_), "MPI_Allreduce");
  return out;
}

std::string MpiDomain::text_of_largest(double value, const std::string& text) const {
  if (!distributed()) return text;  // every process holds every particle: the same text
  struct {
    double value;
    int rank;
  } mine{value, rank_}, largest{};
  check(MPI_Allreduce(&mine, &largest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm_), "MPI_Allreduce");
  uint64_t length = text.size();
  check(MPI_Bcast(&length, 1, MPI_UINT64_T, largest.rank, comm_), "MPI_Bcast");
  std::string out = largest.rank == rank_ ? text : std::string(size_t(length), '\0');
  check(MPI_Bcast(out.data(), record_count(size_t(length)), MPI_CHAR, largest.rank, comm_), "MPI_Bcast");
  return out;
}

void MpiDomain::barrier() const {
  if (size_ > 1) check(MPI_Barrier(comm_), "MPI_Barrier");
}

Real MpiDomain::reduce_min(Real local) const {
  if (!distributed()) return local;
  Real out = local;
  check(MPI_Allreduce(&local, &out, 1, MPI_DOUBLE, MPI_MIN, comm_), "MPI_Allreduce");
  return out;
}

std::vector<Real> MpiDomain::gather_in_rank_order(const Real* local, int count) const {
  std::vector<Real> all(size_t(count) * size_t(size_));
  check(MPI_Allgather(local, count, MPI_DOUBLE, all.data(), count, MPI_DOUBLE, comm_), "MPI_Allgather");
  return all;
}

// Each process's part added in rank order, on every process alike: the same bits
// everywhere, whatever order MPI_Allreduce would take.
Real MpiDomain::reduce_sum(Real local) const {
  if (!distributed()) return local;
  const auto all = gather_in_rank_order(&local, 1);
  Real sum = 0;
  for (Real v : all) sum += v;
  return sum;
}

Vec3 MpiDomain::reduce_sum(const Vec3& local) const {
  if (!distributed()) return local;
  const auto all = gather_in_rank_order(local.data(), 3);
  Vec3 sum = Vec3::Zero();
  for (int r = 0; r < size_; ++r)
    for (int a = 0; a < 3; ++a) sum[a] += all[size_t(3 * r + a)];
  return sum;
}

std::vector<Real> MpiDomain::sum_in_order(const std::vector<uint64_t>& keys, const std::vector<Real>& rows,
                                          size_t width) const {
  if (!distributed()) return sum_rows(rows, width);
  // Every process's items, merged by key.
  const GatheredKeys all = allgather_keys(keys, comm_, size_);
  const std::vector<uint64_t>& all_keys = all.keys;
  const size_t total = all_keys.size();
  const int n = int(keys.size());
  std::vector<int> value_sizes(all.sizes), value_displs(all.displs);
  for (int q = 0; q < size_; ++q) value_sizes[size_t(q)] *= int(width), value_displs[size_t(q)] *= int(width);
  std::vector<Real> all_rows(total * width);
  check(MPI_Allgatherv(rows.data(), n * int(width), MPI_DOUBLE, all_rows.data(), value_sizes.data(),
                       value_displs.data(), MPI_DOUBLE, comm_),
        "MPI_Allgatherv");
  // Items in key order; of a key several processes hold (a grid block on a partition
  // border), the lowest rank's item, the one that comes first in rank order.
  std::vector<uint32_t> order(total);
  for (uint32_t i = 0; i < total; ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](uint32_t a, uint32_t b) { return all_keys[a] != all_keys[b] ? all_keys[a] < all_keys[b] : a < b; });
  std::vector<Real> sum(width, Real(0));
  for (size_t n_th = 0; n_th < total; ++n_th) {
    const uint32_t i = order[n_th];
    if (n_th > 0 && all_keys[order[n_th - 1]] == all_keys[i]) continue;
    for (size_t c = 0; c < width; ++c) sum[c] += all_rows[i * width + c];
  }
  return sum;
}

// Every process's buckets to rank 0, which adds their items in bucket-key order and tells
// the others the sums: a particle sum is not a sum of per-bucket partials.
std::vector<Real> MpiDomain::sum_in_sequence(const std::vector<uint64_t>& keys, const std::vector<uint32_t>& counts,
                                             const std::vector<Real>& rows, size_t width) const {
  if (!distributed()) return sum_rows(rows, width);
  // Items (`width` values each) counted as records: a sum over particles has one per particle.
  const RecordType item(width * sizeof(Real));
  int groups = record_count(keys.size()), items = record_count(rows.size() / width);
  std::vector<int> group_sizes(static_cast<size_t>(size_)), item_sizes(static_cast<size_t>(size_));
  check(MPI_Gather(&groups, 1, MPI_INT, group_sizes.data(), 1, MPI_INT, 0, comm_), "MPI_Gather");
  check(MPI_Gather(&items, 1, MPI_INT, item_sizes.data(), 1, MPI_INT, 0, comm_), "MPI_Gather");
  const auto group_displs = displacements(group_sizes), item_displs = displacements(item_sizes);
  const bool root = rank_ == 0;
  std::vector<uint64_t> all_keys(root ? size_t(group_displs.back()) + size_t(group_sizes.back()) : 0);
  std::vector<uint32_t> all_counts(all_keys.size());
  std::vector<Real> all_rows(root ? (size_t(item_displs.back()) + size_t(item_sizes.back())) * width : 0);
  check(MPI_Gatherv(keys.data(), groups, MPI_UINT64_T, all_keys.data(), group_sizes.data(), group_displs.data(),
                    MPI_UINT64_T, 0, comm_),
        "MPI_Gatherv");
  check(MPI_Gatherv(counts.data(), groups, MPI_UINT32_T, all_counts.data(), group_sizes.data(), group_displs.data(),
                    MPI_UINT32_T, 0, comm_),
        "MPI_Gatherv");
  check(MPI_Gatherv(rows.data(), items, item, all_rows.data(), item_sizes.data(), item_displs.data(), item, 0, comm_),
        "MPI_Gatherv");
  std::vector<Real> sum(width, Real(0));
  if (root) {
    // Where each bucket's items start, then the buckets in key order.
    std::vector<size_t> first(all_keys.size());
    for (int q = 0, g = 0; q < size_; ++q) {
      size_t at = size_t(item_displs[size_t(q)]) * width;
      for (int k = 0; k < group_sizes[size_t(q)]; ++k, ++g) first[size_t(g)] = at, at += all_counts[size_t(g)] * width;
    }
    std::vector<uint32_t> order(all_keys.size());
    for (uint32_t g = 0; g < order.size(); ++g) order[g] = g;
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return all_keys[a] < all_keys[b]; });
    for (uint32_t g : order)
      for (size_t i = 0; i < all_counts[g]; ++i)
        for (size_t c = 0; c < width; ++c) sum[c] += all_rows[first[g] + i * width + c];
  }
  check(MPI_Bcast(sum.data(), int(width), MPI_DOUBLE, 0, comm_), "MPI_Bcast");
  return sum;
}

void MpiDomain::repartition(const Particles& ps, Real inv_h) {
  std::map<uint64_t, uint64_t> local;
  for (size_t p = 0; p < ps.size(); ++p) ++local[morton_key(bucket_of(ps.position[p], inv_h))];
  std::vector<std::pair<uint64_t, uint64_t>> counts(local.begin(), local.end());
  if (distributed_) {
    // Every process's buckets; a bucket entered by particles of several processes since
    // the last sort is listed by each of them.
    std::vector<uint64_t> flat;
    for (const auto& c : counts) flat.push_back(c.first), flat.push_back(c.second);
    const std::vector<uint64_t> all = allgather_keys(flat, comm_, size_).keys;
    std::map<uint64_t, uint64_t> merged;
    for (size_t i = 0; i + 1 < all.size(); i += 2) merged[all[i]] += all[i + 1];
    counts.assign(merged.begin(), merged.end());
  }
  partition_ = partition_buckets(counts, size_);
}

FieldMask MpiDomain::fields_present(const Particles& ps) const {
  FieldMask present;
  for_each_particle_field(ps, [&](const ParticleField& f, const auto& v, const auto&) {
    present.push_back(!(f.optional && v.empty()));
  });
  if (size_ > 1)
    check(MPI_Allreduce(MPI_IN_PLACE, present.data(), int(present.size()), MPI_UINT8_T, MPI_MAX, comm_),
          "MPI_Allreduce");
  return present;
}

void MpiDomain::migrate_particles(Particles& ps, Real cell_size) {
  if (size_ == 1) return;
  const Real inv_h = 1 / cell_size;
  if (!distributed_) {
    // Every process holds every particle: cut the buckets and keep this process's own.
    repartition(ps, inv_h);
    std::vector<uint8_t> keep(ps.size());
    for (size_t p = 0; p < ps.size(); ++p) keep[p] = partition_.owner(bucket_of(ps.position[p], inv_h)) == rank_;
    keep_particles(ps, keep);
    distributed_ = true;
    return;
  }
  // Rebalance when the largest part outgrew the mean (the same decision on every process).
  const double local_count = double(ps.size());
  double largest = 0, total = 0;
  check(MPI_Allreduce(&local_count, &largest, 1, MPI_DOUBLE, MPI_MAX, comm_), "MPI_Allreduce");
  check(MPI_Allreduce(&local_count, &total, 1, MPI_DOUBLE, MPI_SUM, comm_), "MPI_Allreduce");
  if (largest * size_ > imbalance_threshold * total) repartition(ps, inv_h);

  // Each particle to the owner of its bucket.
  std::vector<int> owner(ps.size());
  std::vector<uint8_t> keep(ps.size());
  for (size_t p = 0; p < ps.size(); ++p) {
    owner[p] = partition_.owner(bucket_of(ps.position[p], inv_h));
    keep[p] = owner[p] == rank_;
  }
  const FieldMask present = fields_present(ps);
  const SentParticles sent = send_to_owners(ps, owner, present);
  traffic_.migration_bytes += sent.bytes;
  traffic_.particles_sent += sent.particles;
  keep_particles(ps, keep);
  for (const char* at = sent.received.data(); at < sent.received.data() + sent.received.size();)
    unpack_particle(ps, at, present);
}

MpiDomain::SentParticles MpiDomain::send_to_owners(const Particles& ps, const std::vector<int>& owner,
                                                   const FieldMask& present) const {
  const size_t bytes = particle_bytes(ps, present);
  const RecordType particle(bytes);  // counts in particles
  std::vector<int> send_counts(size_t(size_), 0);
  for (size_t p = 0; p < ps.size(); ++p)
    if (owner[p] != rank_) ++send_counts[size_t(owner[p])];
  std::vector<int> receive_counts(size_t(size_), 0);
  check(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm_), "MPI_Alltoall");
  const auto send_displs = displacements(send_counts), receive_displs = displacements(receive_counts);
  std::vector<char> out((size_t(send_displs.back()) + size_t(send_counts.back())) * bytes);
  SentParticles sent;
  sent.received.resize((size_t(receive_displs.back()) + size_t(receive_counts.back())) * bytes);
  std::vector<size_t> fill(send_displs.begin(), send_displs.end());
  for (size_t p = 0; p < ps.size(); ++p) {
    if (owner[p] == rank_) continue;
    char* at = out.data() + fill[size_t(owner[p])] * bytes;
    pack_particle(ps, p, at, present);
    ++fill[size_t(owner[p])];
    ++sent.particles;
  }
  check(MPI_Alltoallv(out.data(), send_counts.data(), send_displs.data(), particle, sent.received.data(),
                      receive_counts.data(), receive_displs.data(), particle, comm_),
        "MPI_Alltoallv");
  sent.bytes = out.size();
  return sent;
}

void MpiDomain::share_grid(const SparseGrid& grid, const ParticleBuckets& buckets) {
  if (!distributed()) return;
  // 1. Every process's active blocks (sorted keys, as the grid keeps them).
  const int n = int(grid.block_count());
  std::vector<uint64_t> mine(static_cast<size_t>(n));
  for (int b = 0; b < n; ++b) mine[size_t(b)] = grid.key(size_t(b));
  const GatheredKeys all = allgather_keys(mine, comm_, size_);
  auto holds = [&](int q, uint64_t key) {
    const auto first = all.keys.begin() + all.displs[size_t(q)];
    return std::binary_search(first, first + all.sizes[size_t(q)], key);
  };

  // 2. What this process sends after each colour: the nodes of that colour's bucket boxes
  //    in blocks another process holds, bucket by bucket in the colour's order.
  constexpr int bw = SparseGrid::block_width;
  const Real* first = grid.block_count() ? grid.block(0) : nullptr;  // node offsets count from here
  std::array<std::vector<std::vector<int32_t>>, 8> coords;  // node coordinates, 3 per node
  std::vector<int> others;
  for (int k = 0; k < 8; ++k) {
    send_nodes_[size_t(k)].assign(size_t(size_), {});
    coords[size_t(k)].assign(size_t(size_), {});
    for (uint32_t bi : buckets.colours()[size_t(k)]) {
      const Bucket& bucket = buckets.buckets()[bi];
      std::array<int, 3> block_lo, block_hi;
      for (int a = 0; a < 3; ++a)
        block_lo[a] = floor_div(bucket.box_lo[a], bw), block_hi[a] = floor_div(bucket.box_hi[a], bw);
      for (int bx = block_lo[0]; bx <= block_hi[0]; ++bx)
        for (int by = block_lo[1]; by <= block_hi[1]; ++by)
          for (int bz = block_lo[2]; bz <= block_hi[2]; ++bz) {
            const uint64_t key = SparseGrid::block_key(bx, by, bz);
            others.clear();
            for (int q = 0; q < size_; ++q)
              if (q != rank_ && holds(q, key)) others.push_back(q);
            // A block of the box that this process does not hold has no node the bucket's
            // stencils reach (blocks are activated from the node columns, not the box).
            if (others.empty() || grid.find(bx, by, bz) < 0) continue;
            const int c[3] = {bx, by, bz};
            int lo[3], hi[3];
            for (int a = 0; a < 3; ++a)
              lo[a] = std::max(bucket.box_lo[a], bw * c[a]), hi[a] = std::min(bucket.box_hi[a], bw * c[a] + bw - 1);
            for (int i = lo[0]; i <= hi[0]; ++i)
              for (int j = lo[1]; j <= hi[1]; ++j)
                for (int l = lo[2]; l <= hi[2]; ++l) {
                  const size_t offset = size_t(grid.node(i, j, l) - first);
                  for (int q : others) {
                    send_nodes_[size_t(k)][size_t(q)].push_back(offset);
                    auto& xyz = coords[size_t(k)][size_t(q)];
                    xyz.insert(xyz.end(), {i, j, l});
                  }
                }
          }
    }
  }

  // 3. The receivers learn those nodes' coordinates, in the same order.
  std::vector<int> send_counts(size_t(size_) * 8), receive_counts(size_t(size_) * 8);
  for (int q = 0; q < size_; ++q)
    for (int k = 0; k < 8; ++k) send_counts[size_t(q * 8 + k)] = int(coords[size_t(k)][size_t(q)].size());
  check(MPI_Alltoall(send_counts.data(), 8, MPI_INT, receive_counts.data(), 8, MPI_INT, comm_), "MPI_Alltoall");
  std::vector<int> send_total(size_t(size_), 0), receive_total(size_t(size_), 0);
  std::vector<int32_t> out;
  for (int q = 0; q < size_; ++q)
    for (int k = 0; k < 8; ++k) {
      send_total[size_t(q)] += send_counts[size_t(q * 8 + k)];
      receive_total[size_t(q)] += receive_counts[size_t(q * 8 + k)];
      out.insert(out.end(), coords[size_t(k)][size_t(q)].begin(), coords[size_t(k)][size_t(q)].end());
    }
  const auto send_displs = displacements(send_total), receive_displs = displacements(receive_total);
  std::vector<int32_t> in(size_t(receive_displs.back() + receive_total.back()));
  check(MPI_Alltoallv(out.data(), send_total.data(), send_displs.data(), MPI_INT32_T, in.data(), receive_total.data(),
                      receive_displs.data(), MPI_INT32_T, comm_),
        "MPI_Alltoallv");
  traffic_.halo_bytes += out.size() * sizeof(int32_t);
  for (int k = 0; k < 8; ++k) receive_nodes_[size_t(k)].assign(size_t(size_), {});
  for (int q = 0; q < size_; ++q) {
    const int32_t* at = in.data() + receive_displs[size_t(q)];
    for (int k = 0; k < 8; ++k)
      for (int m = 0; m < receive_counts[size_t(q * 8 + k)] / 3; ++m, at += 3) {
        const Real* node = grid.node(at[0], at[1], at[2]);
        if (!node) throw std::logic_error("halo: a shared node's block is not active here");
        receive_nodes_[size_t(k)][size_t(q)].push_back(size_t(node - first));
      }
  }
}

void MpiDomain::exchange_halo(SparseGrid& grid, int colour) {
  if (!distributed()) return;
  const auto& send = send_nodes_[size_t(colour)];
  const auto& receive = receive_nodes_[size_t(colour)];
  constexpr int lanes = lane::count;
  size_t send_size = 0, receive_size = 0;
  for (int q = 0; q < size_; ++q) send_size += send[size_t(q)].size(), receive_size += receive[size_t(q)].size();
  if (send_size + receive_size == 0) return;
  send_buffer_.resize(send_size * lanes);
  receive_buffer_.resize(receive_size * lanes);
  Real* data = grid.block_count() ? grid.block(0) : nullptr;
  std::vector<MPI_Request> requests;
  size_t send_at = 0, receive_at = 0;
  for (int q = 0; q < size_; ++q) {
    if (!receive[size_t(q)].empty()) {
      requests.emplace_back();
      check(MPI_Irecv(receive_buffer_.data() + receive_at, int(receive[size_t(q)].size() * lanes), MPI_DOUBLE, q,
                      colour, comm_, &requests.back()),
            "MPI_Irecv");
      receive_at += receive[size_t(q)].size() * lanes;
    }
    if (!send[size_t(q)].empty()) {
      Real* out = send_buffer_.data() + send_at;
      for (size_t offset : send[size_t(q)]) out = std::copy(data + offset, data + offset + lanes, out);
      requests.emplace_back();
      check(MPI_Isend(send_buffer_.data() + send_at, int(send[size_t(q)].size() * lanes), MPI_DOUBLE, q, colour, comm_,
                      &requests.back()),
            "MPI_Isend");
      send_at += send[size_t(q)].size() * lanes;
    }
  }
  check(MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
  // The sender's lanes are the node's lanes after this colour, as one process has them.
  const Real* in = receive_buffer_.data();
  for (int q = 0; q < size_; ++q)
    for (size_t offset : receive[size_t(q)]) std::copy(in, in + lanes, data + offset), in += lanes;
  traffic_.halo_nodes += send_size;
  traffic_.halo_bytes += send_size * lanes * sizeof(Real);
}

std::vector<BucketSize> MpiDomain::all_bucket_sizes(const std::vector<Bucket>& mine) const {
  std::vector<uint64_t> flat;  // (key, particles, runs) of each bucket here
  for (const BucketSize& b : bucket_sizes(mine)) flat.insert(flat.end(), {b.key, b.particles, b.runs});
  const std::vector<uint64_t> all = allgather_keys(flat, comm_, size_).keys;
  std::vector<BucketSize> sizes;
  for (size_t i = 0; i + 2 < all.size(); i += 3) sizes.push_back({all[i], all[i + 1], all[i + 2]});
  return sizes;
}

BucketPlacement MpiDomain::bucket_placement(const ParticleBuckets& buckets, size_t particles) const {
  if (!distributed()) {  // every process holds every particle (one process's layout): rank 0 writes them
    BucketPlacement placement = place_buckets(bucket_sizes(buckets.buckets()), buckets.buckets(), particles);
    placement.writes = rank_ == 0;
    return placement;
  }
  return place_buckets(all_bucket_sizes(buckets.buckets()), buckets.buckets(), particles);
}

namespace {
// Point ids cut evenly among the processes: process r's block begins here.
size_t id_block_start(size_t total, int r, int processes) { return size_t(uint64_t(total) * uint64_t(r) / uint64_t(processes)); }
}  // namespace

Particles MpiDomain::particles_in_id_block(const Particles& local, size_t total, size_t& first) const {
  first = id_block_start(total, rank_, size_);
  const size_t end = id_block_start(total, rank_ + 1, size_);
  auto owner_of = [&](uint32_t id) {
    int r = int(uint64_t(id) * uint64_t(size_) / std::max<uint64_t>(total, 1));
    while (r + 1 < size_ && id_block_start(total, r + 1, size_) <= id) ++r;
    while (r > 0 && id_block_start(total, r, size_) > id) --r;
    return r;
  };
  Particles block = local;
  std::vector<uint8_t> keep(local.size());
  for (size_t p = 0; p < local.size(); ++p) keep[p] = local.id[p] >= first && local.id[p] < end;
  if (!distributed()) {  // every process holds every particle
    keep_particles(block, keep);
  } else {
    std::vector<int> owner(local.size());
    for (size_t p = 0; p < local.size(); ++p) owner[p] = owner_of(local.id[p]);
    const FieldMask present = fields_present(local);
    const std::vector<char> in = send_to_owners(local, owner, present).received;
    keep_particles(block, keep);
    for (const char* at = in.data(); at < in.data() + in.size();) unpack_particle(block, at, present);
  }
  if (block.size() != end - first) throw std::logic_error("particles_in_id_block: ids missing or repeated");
  std::vector<uint32_t> order(block.size(), UINT32_MAX);
  for (uint32_t p = 0; p < order.size(); ++p) {
    const uint64_t at = block.id[p] - first;  // ids outside [first, end) wrap to large values
    if (at >= order.size() || order[at] != UINT32_MAX) throw std::logic_error("particles_in_id_block: ids missing or repeated");
    order[at] = p;
  }
  block.permute(order);
  return block;
}

void MpiDomain::write_shared_rows(const std::string& path, const std::function<void(Hdf5File&)>& fill) const {
  std::string shared = path;
  if (size_ > 1) {  // rank 0 staged the file under a name of its own: every process opens that one
    uint64_t length = path.size();
    check(MPI_Bcast(&length, 1, MPI_UINT64_T, 0, comm_), "MPI_Bcast");
    shared.resize(size_t(length));
    check(MPI_Bcast(shared.data(), record_count(size_t(length)), MPI_CHAR, 0, comm_), "MPI_Bcast");
  }
  Hdf5File file = size_ > 1 ? open_shared_hdf5(shared, comm_) : Hdf5File(shared, Hdf5File::Mode::read_write);
  try {
    fill(file);
  } catch (const std::exception& e) {
    // The others wait in the next collective write: closing the file here (collective on an
    // MPI-IO file) would hang them. End every process, as a rank-0 failure does.
    if (size_ == 1) throw;
    std::fprintf(stderr, "latmpm-solve: process %d: writing %s: %s\n", rank_, path.c_str(), e.what());
    MPI_Abort(comm_, 2);
  }
  file.close();
}

void MpiDomain::distribute_buckets(Particles& ps, BucketTables& tables) {
  // Every process holds the whole state; without buckets (a run saved before its first
  // sort) it stays so until the first sort cuts it.
  distributed_ = false;
  if (size_ == 1 || tables.buckets.empty()) return;
  std::map<uint64_t, uint64_t> counts;
  for (const Bucket& b : tables.buckets) counts[morton_key(b.coord)] += b.end - b.begin;
  partition_ = partition_buckets({counts.begin(), counts.end()}, size_);
  std::vector<uint8_t> keep(tables.buckets.size());
  for (size_t b = 0; b < keep.size(); ++b) keep[b] = partition_.owner(tables.buckets[b].coord) == rank_;
  keep_particles(ps, select_buckets(tables, keep, ps.size()));
  distributed_ = true;
}

// The one-process order is every process's buckets in bucket order (bucket_layout.hpp): a
// point's index there is the particles of the buckets before its own plus its place in it.
std::vector<ContactSpread> MpiDomain::contact_spreads_in_order(std::vector<ContactSpread> mine,
                                                               const ParticleBuckets& buckets) const {
  if (!distributed()) return mine;  // every process holds every particle, in the one-process order
  const std::vector<Bucket>& local = buckets.buckets();
  const BucketPlacement placement = place_buckets(all_bucket_sizes(local), local, 0);
  for (ContactSpread& s : mine) {
    const auto b = size_t(std::upper_bound(local.begin(), local.end(), s.index,
                                           [](uint64_t p, const Bucket& x) { return p < x.end; }) -
                          local.begin());
    s.index = placement.first_particle.at(b) + (s.index - local[b].begin);
  }
  const RecordType record(sizeof(ContactSpread));
  const int n = record_count(mine.size());
  std::vector<int> sizes(size_t(size_), 0);
  check(MPI_Allgather(&n, 1, MPI_INT, sizes.data(), 1, MPI_INT, comm_), "MPI_Allgather");
  const auto displs = displacements(sizes);
  std::vector<ContactSpread> out(size_t(displs.back()) + size_t(sizes.back()));
  check(MPI_Allgatherv(mine.data(), n, record, out.data(), sizes.data(), displs.data(), record, comm_),
        "MPI_Allgatherv");
  std::sort(out.begin(), out.end(), [](const ContactSpread& a, const ContactSpread& b) { return a.index < b.index; });
  return out;
}

}  // namespace latmpm::mpm
