#include "voxelize/level_set_sampling.hpp"

#include <openvdb/tools/Interpolation.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "levelset/level_set_units.hpp"
#include "voxelize/sub_cell_fraction.hpp"

namespace latmpm {
namespace {

struct Sampled {
  int64_t key;  // lattice index packed in lattice order (see `pack`)
  Eigen::Vector3d position;
  double fraction;  // of Δ³
  double phi;       // signed distance at the point (m)
};

// Lattice order: z slowest, then y, then x — the order the slabs are sampled in, so the
// concatenated keys are sorted and neighbours are found by binary search.
struct LatticeKeys {
  int64_t lo[3], extent[3];
  int64_t pack(int64_t mx, int64_t my, int64_t mz) const {
    return ((mz - lo[2]) * extent[1] + (my - lo[1])) * extent[0] + (mx - lo[0]);
  }
  bool contains(int64_t mx, int64_t my, int64_t mz) const {
    return mx >= lo[0] && my >= lo[1] && mz >= lo[2] && mx < lo[0] + extent[0] &&
           my < lo[1] + extent[1] && mz < lo[2] + extent[2];
  }
};

// A point whose centre lies outside the solid (0 < φ < Δ/2) still carries the part of its
// sub-cell that is inside. Its volume goes to an inside neighbour on the lattice — a face
// neighbour if there is one, else an edge, else a corner neighbour; the deepest (smallest φ)
// among equals, which for a flat surface is the step along the normal. So every point lies
// inside and the total is unchanged. Returns the volume (in Δ³) of outside points that had no
// inside neighbour (a sliver thinner than Δ) and were dropped.
double move_outside_volume_inward(std::vector<Sampled>& all, const LatticeKeys& keys,
                                  double spacing) {
  std::vector<int64_t> sorted_keys(all.size());
  for (size_t i = 0; i < all.size(); ++i) sorted_keys[i] = all[i].key;
  auto find = [&](int64_t mx, int64_t my, int64_t mz) -> long {
    if (!keys.contains(mx, my, mz)) return -1;
    const int64_t key = keys.pack(mx, my, mz);
    auto it = std::lower_bound(sorted_keys.begin(), sorted_keys.end(), key);
    return it != sorted_keys.end() && *it == key ? long(it - sorted_keys.begin()) : -1;
  };
  double dropped = 0;
  for (size_t i = 0; i < all.size(); ++i) {
    if (all[i].phi <= 0) continue;
    const int64_t m[3] = {std::llround(all[i].position.x() / spacing - 0.5),
                          std::llround(all[i].position.y() / spacing - 0.5),
                          std::llround(all[i].position.z() / spacing - 0.5)};
    long best = -1;
    for (int ring = 1; ring <= 3 && best < 0; ++ring)  // nonzero offsets: face 1, edge 2, corner 3
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            if (std::abs(dx) + std::abs(dy) + std::abs(dz) != ring) continue;
            const long j = find(m[0] + dx, m[1] + dy, m[2] + dz);
            if (j >= 0 && all[j].phi <= 0 && (best < 0 || all[j].phi < all[best].phi)) best = j;
          }
    if (best >= 0) all[best].fraction += all[i].fraction;
    else dropped += all[i].fraction;
    all[i].fraction = 0;
  }
  all.erase(std::remove_if(all.begin(), all.end(), [](const Sampled& s) { return s.fraction <= 0; }),
            all.end());
  return dropped;
}

// The level set's voxel size, after checking that index = world / voxel (a pure uniform
// scale, the transform strut_graph_level_set and mesh_level_set create).
double uniform_voxel_size(const openvdb::FloatGrid& grid) {
  const openvdb::math::Transform& xform = grid.transform();
  const openvdb::Vec3d size = xform.voxelSize();
  const double v = size[0];
  const openvdb::Vec3d probe(1.25, -2.5, 3.75);
  const openvdb::Vec3d index = xform.worldToIndex(probe * v);
  const bool uniform = xform.isLinear() && std::fabs(size[1] - v) <= 1e-12 * v &&
                       std::fabs(size[2] - v) <= 1e-12 * v && (index - probe).length() < 1e-9 &&
                       xform.worldToIndex(openvdb::Vec3d(0.0)).length() < 1e-9;
  if (!uniform || !(v > 0))
    throw InputError("voxelize", "level set",
                     "transform is not a uniform scale about the origin (voxel " + std::to_string(v) +
                         " mm, origin at index " + std::to_string(xform.worldToIndex(openvdb::Vec3d(0.0))[0]) + ")");
  return v / grid_units_per_metre;
}

}  // namespace

PointSet sample_level_set(const openvdb::FloatGrid& level_set, const SamplingOptions& options,
                          const std::function<void(double)>& progress, SamplingStats* stats) {
  if (!(options.cell_size > 0) || !std::isfinite(options.cell_size))
    throw InputError("voxelize", "cell size", "must be positive");
  if (options.ppc < 1) throw InputError("voxelize", "ppc", "must be at least 1");
  const double h = options.cell_size;
  const double spacing = h / options.ppc;  // Δ
  const double voxel = uniform_voxel_size(level_set);
  const double background = level_set.background() / grid_units_per_metre;  // m
  // Band points read φ up to one voxel beyond ±Δ/2 for the curvature, and the quick
  // inside/outside test below trusts values up to Δ/2 + √3 voxels: clipped values there
  // would corrupt both.
  if (background < 0.5 * spacing + std::sqrt(3.0) * voxel)
    throw InputError("voxelize", "level set",
                     "narrow band (" + std::to_string(background) + " m) narrower than half a point "
                     "spacing plus √3 voxels: use a wider band");

  PointSet points;
  points.cell_size = h;
  points.ppc = options.ppc;
  const openvdb::CoordBBox active = level_set.evalActiveVoxelBoundingBox();
  if (active.empty()) return points;

  // Lattice indices m with (m + ½)Δ inside the active bounds grown by a voxel.
  int64_t lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = static_cast<int64_t>(std::ceil((active.min()[a] - 1) * voxel / spacing - 0.5));
    hi[a] = static_cast<int64_t>(std::floor((active.max()[a] + 1) * voxel / spacing - 0.5));
  }
  const int64_t slabs = hi[2] - lo[2] + 1;
  LatticeKeys keys;
  for (int a = 0; a < 3; ++a) {
    keys.lo[a] = lo[a];
    keys.extent[a] = std::max<int64_t>(hi[a] - lo[a] + 1, 1);
  }
  std::vector<std::vector<Sampled>> per_slab(static_cast<size_t>(std::max<int64_t>(slabs, 0)));

  // The trilinear value at a point differs from its nearest voxel's by at most √3 voxels
  // (φ is 1-Lipschitz): points clearly outside or inside skip the interpolation.
  const double margin = 0.5 * spacing + std::sqrt(3.0) * voxel;
  const double inv_voxel = 1.0 / voxel;
  auto sample_slab = [&](int64_t mz) {
    auto accessor = level_set.getConstAccessor();
    // φ in metres (the grid holds grid units, level_set_units.hpp).
    auto phi_at = [&](const openvdb::Vec3d& index) {
      return static_cast<double>(openvdb::tools::BoxSampler::sample(accessor, index)) / grid_units_per_metre;
    };
    std::vector<Sampled>& out = per_slab[static_cast<size_t>(mz - lo[2])];
    const double z = (mz + 0.5) * spacing;
    for (int64_t my = lo[1]; my <= hi[1]; ++my) {
      const double y = (my + 0.5) * spacing;
      for (int64_t mx = lo[0]; mx <= hi[0]; ++mx) {
        const double x = (mx + 0.5) * spacing;
        const openvdb::Vec3d index(x * inv_voxel, y * inv_voxel, z * inv_voxel);
        const double nearest = accessor.getValue(openvdb::Coord::round(index)) / grid_units_per_metre;
        if (nearest >= margin) continue;
        double fraction = 1.0;
        double phi = nearest;
        if (nearest > -margin) {
          phi = phi_at(index);
          double curvature = 0.0;
          if (options.curvature_correction && std::fabs(phi) < 0.5 * spacing) {
            // ∇²φ by central differences one voxel apart.
            double sum = -6.0 * phi;
            for (int a = 0; a < 3; ++a) {
              openvdb::Vec3d step(0.0);
              step[a] = 1.0;
              sum += phi_at(index + step) + phi_at(index - step);
            }
            curvature = sum * inv_voxel * inv_voxel;
          }
          fraction = sub_cell_fraction(phi, curvature, spacing);
        }
        if (fraction > 0) out.push_back({keys.pack(mx, my, mz), Eigen::Vector3d(x, y, z), fraction, phi});
      }
    }
  };

  // Chunks of slabs in parallel; progress reported between chunks from this thread.
  const int64_t chunk = std::max<int64_t>(1, slabs / 20);
  for (int64_t start = lo[2]; start <= hi[2]; start += chunk) {
    const int64_t stop = std::min(hi[2] + 1, start + chunk);
    tbb::parallel_for(tbb::blocked_range<int64_t>(start, stop, 1),
                      [&](const tbb::blocked_range<int64_t>& r) {
                        for (int64_t mz = r.begin(); mz != r.end(); ++mz) sample_slab(mz);
                      });
    if (progress) progress(double(stop - lo[2]) / double(slabs));
  }

  size_t total = 0;
  for (const auto& s : per_slab) total += s.size();
  std::vector<Sampled> all;
  all.reserve(total);
  for (auto& slab : per_slab) {
    all.insert(all.end(), slab.begin(), slab.end());
    std::vector<Sampled>().swap(slab);
  }
  const double full = spacing * spacing * spacing;
  const double dropped = full * move_outside_volume_inward(all, keys, spacing);
  if (stats) stats->dropped_volume = dropped;
  total = all.size();
  points.position.reserve(total);
  points.volume.reserve(total);
  for (const Sampled& s : all) {
    points.position.push_back(s.position);
    points.volume.push_back(full * s.fraction);
  }
  points.body.assign(total, 0);
  points.half_size.assign(total, Eigen::Vector3d::Constant(0.5 * spacing));
  return points;
}

}  // namespace latmpm
