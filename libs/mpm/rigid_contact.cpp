#include "mpm/rigid_contact.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace latmpm::mpm {

bool has_penalty_contact(const std::vector<RigidBodySettings>& bodies) {
  return std::any_of(bodies.begin(), bodies.end(),
                     [](const RigidBodySettings& b) { return b.coupling == RigidCoupling::penalty; });
}

ContactProbe probe_contact(const RigidBodySettings& b, const Vec3& d, const Vec3& x, const Vec3& half) {
  ContactProbe probe;
  if (b.shape == RigidShape::half_space) {
    const Vec3 n = b.plane_normal.normalized();
    const Real reach = n.cwiseAbs().dot(half);
    const Real gap = (x - b.plane_point - d).dot(n) - reach;
    if (gap < 0) probe = {true, n, -gap};
    return probe;
  }
  // The box grown by the point's half-sizes; inside it, the face nearest the point.
  Real depth = std::numeric_limits<Real>::infinity();
  Vec3 normal = Vec3::Zero();
  for (int a = 0; a < 3; ++a) {
    const Real below = x[a] - (b.box_min[a] + d[a] - half[a]);  // depth behind the lower face
    const Real above = (b.box_max[a] + d[a] + half[a]) - x[a];  // behind the upper face
    if (!(below > 0 && above > 0)) return probe;
    if (below < depth) depth = below, normal = -Vec3::Unit(a);
    if (above < depth) depth = above, normal = Vec3::Unit(a);
  }
  return {true, normal, depth};
}

ContactForce penalty_contact_force(const Vec3& anchor, const Vec3& x, const ContactProbe& probe, Real stiffness,
                                   Real friction) {
  const Vec3& n = probe.normal;
  const Vec3 closest = x + probe.depth * n;
  // The normal part from the depth, the tangential part from the anchor's offset along the
  // surface (the anchor of a half-space stays on its surface; one of a box may sit on
  // another face after the point rounded an edge: only its tangential offset counts).
  const Real normal_force = stiffness * probe.depth;
  const Vec3 offset = anchor - x;
  Vec3 tangential = stiffness * (offset - offset.dot(n) * n);
  ContactForce out;
  if (std::isfinite(friction)) {
    const Real limit = friction * normal_force, size = tangential.norm();
    if (size > limit) {
      // Relax the anchor toward the closest point onto the friction cone: |f_t| = μ f_n.
      tangential = size > 0 ? Vec3(tangential * (limit / size)) : Vec3::Zero();
      out.sliding = true;
      out.friction_work = limit * (size - limit) / stiffness;
    }
  }
  out.force = normal_force * n + tangential;
  out.anchor = closest + tangential / stiffness;
  out.spring_energy = Real(0.5) * out.force.squaredNorm() / stiffness;
  return out;
}

Real default_contact_stiffness_per_mass(Real wave_speed_squared, Real h) { return wave_speed_squared / (h * h); }

namespace {
Real point_stiffness(const RigidBodySettings& body, const ContactMaterial& material, Real mass) {
  return body.contact_stiffness > 0 ? body.contact_stiffness : mass * material.stiffness_per_mass;
}

// Fixed chunks of points: per-chunk lists and sums joined in chunk order (deterministic).
constexpr size_t chunk = 4096;
}  // namespace

void update_penalty_contacts(Particles& ps, const std::vector<ContactMaterial>& materials,
                             const std::vector<RigidBodySettings>& bodies,
                             const std::vector<RigidBodyState>& states, ContactForces& out) {
  const size_t n = ps.size(), nb = bodies.size(), chunks = (n + chunk - 1) / chunk;
  std::vector<size_t> penalty;
  for (size_t k = 0; k < nb; ++k)
    if (bodies[k].coupling == RigidCoupling::penalty) penalty.push_back(k);
  out.force.assign(n, Vec3::Zero());
  out.reaction.assign(nb, Vec3::Zero());
  out.spring_energy.assign(nb, 0);
  out.friction_work.assign(nb, 0);
  out.touching.clear();
  out.touching_spring.clear();
  out.touching_friction.clear();
  std::vector<std::vector<uint32_t>> touching(chunks);
  std::vector<std::vector<Real>> touching_spring(chunks), touching_friction(chunks);
  std::vector<Vec3> chunk_reaction(chunks * nb, Vec3::Zero());
  std::vector<Real> chunk_spring(chunks * nb, 0), chunk_friction(chunks * nb, 0);
  tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
    for (size_t p = c * chunk; p < std::min(n, (c + 1) * chunk); ++p) {
      const ContactMaterial& material = materials[size_t(ps.body[p])];
      if (!material.deformable) continue;
      const Vec3& x = ps.position[p];
      int32_t& k = ps.contact_body[p];
      Vec3& anchor = ps.contact_anchor[p];
      // The domain's half-sizes, or none where the body takes contact at the material point.
      const Vec3 half = ps.half_size0[p].cast<Real>();
      auto reach = [&](size_t body) {
        return bodies[body].contact_reach == ContactReach::point ? Vec3(Vec3::Zero()) : half;
      };
      ContactProbe probe;
      if (k >= 0) {
        probe = probe_contact(bodies[size_t(k)], states[size_t(k)].displacement, x, reach(size_t(k)));
        if (!probe.penetrates) k = -1;  // it left the surface: contact ends
      }
      if (k < 0) {
        for (size_t body : penalty) {
          probe = probe_contact(bodies[body], states[body].displacement, x, reach(body));
          if (!probe.penetrates) continue;
          // First contact: the attachment point is the closest point of the surface.
          k = int32_t(body);
          anchor = x + probe.depth * probe.normal - states[body].displacement;
          break;
        }
        if (k < 0) continue;
      }
      const RigidBodySettings& body = bodies[size_t(k)];
      const Vec3& d = states[size_t(k)].displacement;
      const ContactForce f =
          penalty_contact_force(anchor + d, x, probe, point_stiffness(body, material, ps.mass[p]), body.friction);
      anchor = f.anchor - d;
      out.force[p] = f.force;
      chunk_reaction[c * nb + size_t(k)] += f.force;
      chunk_spring[c * nb + size_t(k)] += f.spring_energy;
      chunk_friction[c * nb + size_t(k)] += f.friction_work;
      touching[c].push_back(uint32_t(p));
      touching_spring[c].push_back(f.spring_energy);
      touching_friction[c].push_back(f.friction_work);
    }
  });
  for (size_t c = 0; c < chunks; ++c) {
    out.touching.insert(out.touching.end(), touching[c].begin(), touching[c].end());
    out.touching_spring.insert(out.touching_spring.end(), touching_spring[c].begin(), touching_spring[c].end());
    out.touching_friction.insert(out.touching_friction.end(), touching_friction[c].begin(), touching_friction[c].end());
    for (size_t k = 0; k < nb; ++k) {
      out.reaction[k] += chunk_reaction[c * nb + k];
      out.spring_energy[k] += chunk_spring[c * nb + k];
      out.friction_work[k] += chunk_friction[c * nb + k];
    }
  }
}

void contact_sums_in_order(const std::vector<ContactSpread>& spreads, size_t nb, ContactForces& out) {
  out.reaction.assign(nb, Vec3::Zero());
  out.spring_energy.assign(nb, 0);
  out.friction_work.assign(nb, 0);
  // A chunk without touching points adds zeros (x + 0 = x): only the touched chunks count.
  std::vector<Vec3> chunk_reaction(nb);
  std::vector<Real> chunk_spring(nb), chunk_friction(nb);
  for (size_t i = 0; i < spreads.size();) {
    const uint64_t c = spreads[i].index / chunk;
    std::fill(chunk_reaction.begin(), chunk_reaction.end(), Vec3::Zero());
    std::fill(chunk_spring.begin(), chunk_spring.end(), Real(0));
    std::fill(chunk_friction.begin(), chunk_friction.end(), Real(0));
    for (; i < spreads.size() && spreads[i].index / chunk == c; ++i) {
      const ContactSpread& s = spreads[i];
      const auto k = size_t(s.body);
      chunk_reaction[k] += Vec3(s.force[0], s.force[1], s.force[2]);
      chunk_spring[k] += s.spring_energy;
      chunk_friction[k] += s.friction_work;
    }
    for (size_t k = 0; k < nb; ++k) {
      out.reaction[k] += chunk_reaction[k];
      out.spring_energy[k] += chunk_spring[k];
      out.friction_work[k] += chunk_friction[k];
    }
  }
}

Real stable_contact_rate_squared(const Particles& ps, const std::vector<ContactMaterial>& materials,
                                 const std::vector<RigidBodySettings>& bodies) {
  Real rate = 0;
  for (const auto& body : bodies) {
    if (body.coupling != RigidCoupling::penalty) continue;
    for (size_t p = 0; p < ps.size(); ++p) {
      const ContactMaterial& material = materials[size_t(ps.body[p])];
      if (material.deformable && ps.mass[p] > 0)
        rate = std::max(rate, point_stiffness(body, material, ps.mass[p]) / ps.mass[p]);
    }
  }
  return rate;
}

}  // namespace latmpm::mpm
