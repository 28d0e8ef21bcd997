// Grid contact between velocity fields (field_contact.hpp): the fields of the points, the
// fields' lanes against the grid's, and the contact rule on the nodes.
#include "mpm/field_contact.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "mpm/body.hpp"
#include "points/point_set.hpp"

namespace latmpm::mpm {

namespace {
// The lowest field of a non-empty mask.
int lowest_field(uint32_t mask) { return __builtin_ctz(mask); }

// The group tags: each name as given, "prefix*" as every tag of the point set starting
// with prefix (in name order: the strut groups strut_c0, strut_c1, ... of a lattice).
std::vector<std::string> expand_groups(const std::vector<std::string>& names, const PointSet& points,
                                       const std::string& where) {
  std::vector<std::string> tags;
  for (const std::string& name : names) {
    const bool pattern = !name.empty() && name.back() == '*';
    const std::string prefix = pattern ? name.substr(0, name.size() - 1) : name;
    const size_t before = tags.size();
    for (const auto& [tag, mask] : points.tags)
      if (pattern ? tag.compare(0, prefix.size(), prefix) == 0 : tag == name) tags.push_back(tag);
    if (tags.size() == before)
      throw InputError(where, "contact.groups",
                       pattern ? "no tag of the point set starts with '" + prefix + "'" : "the point set has no tag '" + name + "'");
  }
  return tags;
}
}  // namespace

ContactFields make_contact_fields(const FieldContactSettings& settings, Real mass_scaling, const PointSet& points,
                                  const std::vector<BodySettings>& bodies, std::vector<uint8_t>& point_field,
                                  const std::string& where) {
  ContactFields f;
  f.friction = settings.friction;
  if (bodies.size() > size_t(max_contact_bodies))
    throw InputError(where, "contact", "grid contact takes at most " + std::to_string(max_contact_bodies) +
                                           " bodies (the scene has " + std::to_string(bodies.size()) + ")");
  // Field 0 holds the first deformable body's rest and every rigid point (rigid points
  // only mark constraints); each further deformable body and each (body, group) pair
  // present gets the next field.
  const size_t nb = bodies.size();
  std::vector<int> body_field(nb, -1);
  auto new_field = [&](const std::string& name) {
    if (f.count == max_contact_fields)
      throw InputError(where, "contact.groups", "grid contact takes at most " + std::to_string(max_contact_fields) +
                                                    " fields (bodies × groups present); this scene needs more");
    f.names.push_back(name);
    f.density.push_back(0);
    f.bonded.push_back(uint32_t(1) << f.count);
    return f.count++;
  };
  f.fill = settings.fill;
  auto body_density = [&](size_t b) { return bodies[b].material.density * mass_scaling; };
  for (size_t b = 0; b < nb; ++b)
    if (bodies[b].role == BodyRole::deformable) {
      body_field[b] = new_field(bodies[b].name);
      f.density[size_t(body_field[b])] = body_density(b);
    }
  if (f.count == 0) new_field("rigid");
  // Bodies glued where they meet: their rest fields bonded (a lattice and its printed plate).
  uint32_t glued = 0;
  for (const std::string& name : settings.bonded_bodies) {
    size_t b = 0;
    while (b < nb && bodies[b].name != name) ++b;
    if (b == nb || body_field[b] < 0)
      throw InputError(where, "contact.bond", "'" + name + "' is not a deformable body of the scene");
    glued |= uint32_t(1) << body_field[b];
  }
  for (uint32_t rest = glued; rest; rest &= rest - 1) f.bonded[size_t(lowest_field(rest))] |= glued;
  const std::vector<std::string> groups = expand_groups(settings.groups, points, where);
  std::vector<const std::vector<uint8_t>*> tags;
  for (const auto& tag : groups) tags.push_back(&points.tags.at(tag));
  std::vector<std::vector<int>> group_field(nb, std::vector<int>(groups.size(), -1));
  point_field.assign(points.size(), 0);
  for (size_t p = 0; p < points.size(); ++p) {
    const size_t b = size_t(points.body[p]);
    if (bodies[b].role != BodyRole::deformable) continue;  // field 0
    int field = body_field[b];
    for (size_t g = 0; g < tags.size(); ++g) {  // the first group tag the point carries
      if (!(*tags[g])[p]) continue;
      int& gf = group_field[b][g];
      if (gf < 0) {
        gf = new_field(bodies[b].name + "/" + groups[g]);
        f.density[size_t(gf)] = body_density(b);
        // A group moves with the rest of its body where they meet: the joints.
        f.bonded[size_t(gf)] |= uint32_t(1) << body_field[b];
        f.bonded[size_t(body_field[b])] |= uint32_t(1) << gf;
      }
      field = gf;
      break;
    }
    point_field[p] = uint8_t(field);
  }
  for (size_t g = 0; g < groups.size(); ++g) {
    bool any = false;
    for (size_t b = 0; b < nb; ++b) any = any || group_field[b][g] >= 0;
    if (!any) throw InputError(where, "contact.groups", "no deformable point carries the tag '" + groups[g] + "'");
  }
  f.lanes.resize(size_t(f.count));
  return f;
}

BucketTally empty_tally() {
  BucketTally t;
  t.cell_min = {max_cell_coord, max_cell_coord, max_cell_coord};
  t.cell_max = {-max_cell_coord, -max_cell_coord, -max_cell_coord};
  return t;
}

void merge_tally(BucketTally& into, const BucketTally& from) {
  into.kinetic += from.kinetic;
  into.strain += from.strain;
  into.gravity_power += from.gravity_power;
  into.dissipation += from.dissipation;
  into.blend_dissipation += from.blend_dissipation;
  into.increment_energy += from.increment_energy;
  into.max_speed_sq = std::max(into.max_speed_sq, from.max_speed_sq);
  into.max_wave_speed_sq = std::max(into.max_wave_speed_sq, from.max_wave_speed_sq);
  for (int a = 0; a < 3; ++a) {
    into.cell_min[a] = std::min(into.cell_min[a], from.cell_min[a]);
    into.cell_max[a] = std::max(into.cell_max[a], from.cell_max[a]);
  }
  into.cells.merge(from.cells);
  into.drifted = into.drifted || from.drifted;
  if (into.fault == ParticleFault::none) into.fault = from.fault, into.fault_particle = from.fault_particle;
}

namespace {
template <class Fn>
void for_each_block(const SparseGrid& grid, Fn&& fn) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, grid.block_count(), 8), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t b = r.begin(); b < r.end(); ++b) fn(b);
  });
}

constexpr int bw = SparseGrid::block_width;

// Mass of the fields in `mask` at node (i, j, k); 0 on an inactive block.
Real field_mass(const SparseGrid& grid, const ContactFields& f, uint32_t mask, int i, int j, int k) {
  const std::ptrdiff_t node = grid.node_index(i, j, k);
  if (node < 0) return 0;
  const size_t at = size_t(node) + lane::mass;
  Real m = 0;
  for (uint32_t rest = mask; rest; rest &= rest - 1) m += f.lanes[size_t(lowest_field(rest))][at];
  return m;
}

// A field's free momentum at a node, p + dt f (its momentum and force lanes).
Vec3 free_momentum(const Real* lanes, Real dt) {
  return Vec3(lanes[lane::momentum], lanes[lane::momentum + 1], lanes[lane::momentum + 2]) +
         dt * Vec3(lanes[lane::force], lanes[lane::force + 1], lanes[lane::force + 2]);
}

// ∇ of the nodal mass of the fields in `mask` at node (i, j, k), central differences.
Vec3 field_mass_gradient(const SparseGrid& grid, const ContactFields& f, uint32_t mask, int i, int j, int k, Real h) {
  const Real s = 1 / (2 * h);
  return Vec3(field_mass(grid, f, mask, i + 1, j, k) - field_mass(grid, f, mask, i - 1, j, k),
              field_mass(grid, f, mask, i, j + 1, k) - field_mass(grid, f, mask, i, j - 1, k),
              field_mass(grid, f, mask, i, j, k + 1) - field_mass(grid, f, mask, i, j, k - 1)) * s;
}

// The fields of `present` that move with field `first` where they meet: the closure of
// the bonds over the fields on the node.
uint32_t bonded_cluster(const ContactFields& f, uint32_t present, int first) {
  uint32_t cluster = uint32_t(1) << first, grown = cluster;
  do {
    cluster = grown;
    for (uint32_t rest = cluster; rest; rest &= rest - 1) grown |= f.bonded[size_t(lowest_field(rest))] & present;
  } while (grown != cluster);
  return cluster;
}
}  // namespace

void clear_field_lanes(const SparseGrid& grid, ContactFields& fields) {
  for (auto& lanes : fields.lanes) lanes.assign(grid.lane_values(), Real(0));
}

void sum_fields_into_grid(SparseGrid& grid, const ContactFields& f) {
  for_each_block(grid, [&](size_t b) {
    Real* block = grid.block(b);
    const size_t first = b * SparseGrid::reals_per_block;
    for (int v = 0; v < SparseGrid::reals_per_block; v += lane::count) {
      Real* node = block + v;
      for (int k = 0; k < f.count; ++k) {
        const Real* field = f.lanes[size_t(k)].data() + first + size_t(v);
        for (int l = 0; l < lane::constraint; ++l) node[l] += field[l];
        node[lane::constraint] = std::max(node[lane::constraint], field[lane::constraint]);
      }
    }
  });
}

void apply_field_contact(SparseGrid& grid, ContactFields& f, Real dt, const Vec3& gravity, Real h) {
  std::vector<size_t> nodes(grid.block_count(), 0);
  std::vector<Real> dissipated(grid.block_count(), 0);
  const Real mu = f.friction;
  const Real cell_volume = h * h * h;
  for_each_block(grid, [&](size_t b) {
    Real* block = grid.block(b);
    const auto coord = grid.coord(b);
    const size_t first = b * SparseGrid::reals_per_block;
    for (int n = 0; n < SparseGrid::nodes_per_block; ++n) {
      const size_t at = first + size_t(n) * lane::count;
      Real* node = block + n * lane::count;
      uint32_t present = 0;
      for (int k = 0; k < f.count; ++k)
        if (f.lanes[size_t(k)][at + lane::mass] > 0) present |= uint32_t(1) << k;
      if (present == 0) continue;
      const uint32_t cluster0 = bonded_cluster(f, present, lowest_field(present));
      const bool separate = cluster0 != present && node[lane::constraint] == 0;
      if (!separate) {  // one field, bonded fields or a boundary: the centre of mass's velocity
        for (uint32_t rest = present; rest; rest &= rest - 1) {
          Real* lanes = f.lanes[size_t(lowest_field(rest))].data() + at;
          for (int l = lane::momentum; l < lane::constraint; ++l) lanes[l] = node[l];
        }
        continue;
      }
      // Free velocities: v* = (p + dt f)/m + dt g, of the centre of mass and of each cluster.
      const Real m = node[lane::mass];
      Vec3 q_all = Vec3::Zero();
      for (uint32_t rest = present; rest; rest &= rest - 1) {
        q_all += free_momentum(f.lanes[size_t(lowest_field(rest))].data() + at, dt);
      }
      const Vec3 v_cm_free = q_all / m + dt * gravity;
      const Vec3 v_cm(node[lane::momentum], node[lane::momentum + 1], node[lane::momentum + 2]);
      const int i = bw * coord[0] + n / (bw * bw), j = bw * coord[1] + (n / bw) % bw, k = bw * coord[2] + n % bw;
      // The volume check: the fields touch only where they fill the node; else each moves freely.
      Real volume = 0;
      for (uint32_t rest = present; rest; rest &= rest - 1) {
        const size_t field = size_t(lowest_field(rest));
        if (f.density[field] > 0) volume += f.lanes[field][at + lane::mass] / f.density[field];
      }
      const bool touching = volume >= f.fill * cell_volume;
      bool approached = false;
      for (uint32_t left = present; left;) {
        const uint32_t cluster = bonded_cluster(f, present, lowest_field(left));
        left &= ~cluster;
        Real m_k = 0;
        Vec3 q = Vec3::Zero();
        for (uint32_t rest = cluster; rest; rest &= rest - 1) {
          const Real* lanes = f.lanes[size_t(lowest_field(rest))].data() + at;
          m_k += lanes[lane::mass];
          q += free_momentum(lanes, dt);
        }
        const Vec3 delta_free = q / m_k + dt * gravity - v_cm_free;
        Vec3 delta = delta_free;
        // From this cluster toward the others, along the mass gradient of whichever side
        // has more mass on the node (Nairn 2013: the flat face of a block, not the tilted
        // gradient at the edge of the block sliding on it, which would plough). Ties go to
        // the side holding the lowest field. For two clusters the normals are exactly
        // opposite, so their corrections exchange equal and opposite momentum.
        const uint32_t others = present & ~cluster;
        const Vec3 g_own = field_mass_gradient(grid, f, cluster, i, j, k, h);
        const Vec3 g_others = field_mass_gradient(grid, f, others, i, j, k, h);
        const Real s_own = g_own.squaredNorm(), s_others = g_others.squaredNorm();
        const bool own = s_own > s_others || (s_own == s_others && lowest_field(cluster) < lowest_field(others));
        const Vec3 normal = own ? Vec3(-g_own) : g_others;
        const Real norm = normal.norm();
        if (!touching) {
          // apart: the free velocity
        } else if (norm > 0) {
          const Vec3 nn = normal / norm;
          const Real dn = delta.dot(nn);
          if (dn > 0) {  // approaching: take the normal part out, friction on the tangential
            approached = true;
            const Vec3 dt_part = delta - dn * nn;
            const Real slip = dt_part.norm();
            delta = dt_part;
            if (slip > 0) delta -= std::min(mu * dn, slip) / slip * dt_part;
          }
        } else {
          delta = Vec3::Zero();  // no normal (inside a mixed region): move with the centre of mass
        }
        const Vec3 v = v_cm + delta;
        dissipated[b] += Real(0.5) * m_k * ((v_cm + delta_free).squaredNorm() - v.squaredNorm());
        for (uint32_t rest = cluster; rest; rest &= rest - 1) {
          Real* lanes = f.lanes[size_t(lowest_field(rest))].data() + at;
          const Vec3 v_old = Vec3(lanes[lane::momentum], lanes[lane::momentum + 1], lanes[lane::momentum + 2]) / lanes[lane::mass];
          for (int a = 0; a < 3; ++a) lanes[lane::momentum + a] = v[a], lanes[lane::force + a] = v[a] - v_old[a];
        }
      }
      nodes[b] += approached;
    }
  });
  f.contact_nodes = 0;
  f.dissipated = 0;
  for (size_t b = 0; b < nodes.size(); ++b) f.contact_nodes += nodes[b], f.dissipated += dissipated[b];
}

}  // namespace latmpm::mpm
