#include "mpm/observers.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

#include "core/errors.hpp"
#include "mpm/bucket_partition.hpp"
#include "mpm/deformation.hpp"
#include "mpm/simd.hpp"

namespace latmpm::mpm {

BodiesApartCheck::BodiesApartCheck(const Simulation& sim) {
  const size_t nb = sim.bodies().size();
  const Particles& ps = sim.particles();
  lo_.assign(nb, Vec3::Constant(std::numeric_limits<Real>::infinity()));
  hi_.assign(nb, Vec3::Constant(-std::numeric_limits<Real>::infinity()));
  pad_.assign(nb, Vec3::Zero());
  for (size_t p = 0; p < ps.size(); ++p) {
    const size_t b = size_t(ps.body[p]);
    lo_[b] = lo_[b].cwiseMin(ps.position[p]);
    hi_[b] = hi_[b].cwiseMax(ps.position[p]);
    pad_[b] = pad_[b].cwiseMax(ps.half_size0[p].cast<Real>());
  }
}

// A driven body that has reached a fixed one along its direction of motion, with their
// footprints overlapping, has squeezed out all the material between them: their
// constraints then fight over the same nodes and the run goes on with nonsense (measured: a
// plate driven 20 mm into a 16 mm column finished, the column's points dragged through the
// base, 88 % of the work unaccounted for). Point bodies by their points' box plus the points'
// domain half-size (the body's surface), rigid boxes by their geometry. (Closer than a cell
// is allowed: paper-style densification runs end with less than a cell of material left.)
// Fixed rigid bodies count like fixed point bodies: a box by its geometry; a half-space,
// unbounded across its normal, has no footprint to miss, so a driven body approaching it
// is caught once its nearest corner crosses the surface. (Driven half-spaces, unbounded
// themselves, are not checked.)
void BodiesApartCheck::operator()(const Simulation& sim, const StepDiagnostics& now) const {
  const auto& bodies_ = sim.bodies();
  const auto& rigid_bodies_ = sim.rigid_bodies();
  const auto& rigid = sim.rigid_states();
  struct Box {
    std::string name;
    Vec3 lo, hi, velocity;
  };
  auto fail = [&](const std::string& driven_name, const std::string& fixed_name, Real gap) {
    std::ostringstream msg;
    msg << "step " << now.step << " (t = " << now.time << " s): the driven body '" << driven_name
        << "' has reached the fixed body '" << fixed_name << "' (gap " << gap
        << " m): no material is left between them to compress, and their constraints would fight over "
           "the same grid nodes; end the run earlier (run.end)";
    throw NumericalError(msg.str());
  };
  std::vector<Box> driven, fixed;
  for (size_t b = 0; b < bodies_.size(); ++b) {
    if (bodies_[b].role == BodyRole::deformable || !(lo_[b][0] <= hi_[b][0])) continue;
    Box box{bodies_[b].name, lo_[b] - pad_[b], hi_[b] + pad_[b], bodies_[b].velocity};
    if (bodies_[b].role == BodyRole::fixed) {
      fixed.push_back(box);
    } else {
      box.lo += now.body_displacement[b];
      box.hi += now.body_displacement[b];
      driven.push_back(box);
    }
  }
  for (size_t k = 0; k < rigid_bodies_.size(); ++k)
    if (rigid_bodies_[k].motion == RigidMotion::driven && rigid_bodies_[k].shape == RigidShape::box)
      driven.push_back({rigid_bodies_[k].name, rigid_bodies_[k].box_min + rigid[k].displacement,
                        rigid_bodies_[k].box_max + rigid[k].displacement, rigid[k].velocity});
  std::vector<size_t> fixed_half_spaces;
  for (size_t k = 0; k < rigid_bodies_.size(); ++k) {
    if (rigid_bodies_[k].motion != RigidMotion::fixed) continue;
    if (rigid_bodies_[k].shape == RigidShape::box)
      fixed.push_back({rigid_bodies_[k].name, rigid_bodies_[k].box_min, rigid_bodies_[k].box_max, Vec3::Zero()});
    else
      fixed_half_spaces.push_back(k);
  }
  for (const Box& d : driven) {
    if (!(d.velocity.norm() > 0)) continue;
    const Vec3 a = d.velocity.normalized();
    for (const Box& f : fixed) {
      // Footprints across a overlap (the boxes overlap in the plane normal to a) ...
      bool across = true;
      for (int axis = 0; axis < 3; ++axis)
        if (std::abs(a[axis]) < 0.5 && (d.hi[axis] < f.lo[axis] || f.hi[axis] < d.lo[axis])) across = false;
      if (!across) continue;
      // ... and the gap along a, from the driven body's front to the fixed body's back.
      Real front = -std::numeric_limits<Real>::infinity(), back = std::numeric_limits<Real>::infinity();
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3 cd((corner & 1) ? d.hi[0] : d.lo[0], (corner & 2) ? d.hi[1] : d.lo[1], (corner & 4) ? d.hi[2] : d.lo[2]);
        const Vec3 cf((corner & 1) ? f.hi[0] : f.lo[0], (corner & 2) ? f.hi[1] : f.lo[1], (corner & 4) ? f.hi[2] : f.lo[2]);
        front = std::max(front, cd.dot(a));
        back = std::min(back, cf.dot(a));
      }
      // Bodies that start apart (or touching) and close to less than a cell; a fixed body
      // behind the driven one, or beside it along a, never counts.
      const Real gap = back - front, start_gap = gap + d.velocity.norm() * now.time;
      if (!(start_gap >= 0 && gap <= 0)) continue;
      fail(d.name, f.name, gap);
    }
    for (size_t k : fixed_half_spaces) {
      // The gap along the half-space's normal n, from its surface to the box's nearest corner;
      // it closes at −V·n, so a box moving along or away from the surface never counts.
      const RigidBodySettings& f = rigid_bodies_[k];
      const Vec3 n = f.plane_normal.normalized();
      const Real closing = -d.velocity.dot(n);
      if (!(closing > 0)) continue;
      Real gap = std::numeric_limits<Real>::infinity();
      for (int corner = 0; corner < 8; ++corner) {
        const Vec3 cd((corner & 1) ? d.hi[0] : d.lo[0], (corner & 2) ? d.hi[1] : d.lo[1], (corner & 4) ? d.hi[2] : d.lo[2]);
        gap = std::min(gap, (cd - f.plane_point).dot(n));
      }
      const Real start_gap = gap + closing * now.time;
      if (start_gap >= 0 && gap <= 0) fail(d.name, f.name, gap);
    }
  }
}


Real RecordLayerForce::operator()(const Simulation& sim) const {
  if (!(area_ > 0)) return 0;
  const SolverState& state = sim.state();
  const Particles& ps = state.particles;
  const auto& runs = state.buckets.runs();
  std::vector<Real> rows;  // per bucket: Σ σ_zz V, Σ V of its record points
  for (const Bucket& b : state.buckets.buckets()) {
    Pack bucket_stress_volume{}, bucket_volume{};
    for (uint32_t r = b.run_begin; r < b.run_end; ++r) {
      const BodyRun& run = runs[r];
      if (sim.bodies()[size_t(run.body)].role != BodyRole::deformable) continue;
      for (uint32_t g0 = run.begin; g0 < run.end; g0 += pack_width) {
        const int n = int(std::min<uint32_t>(pack_width, run.end - g0));
        // A group without record points adds zeros; lanes of other points hold zero volume.
        Pack record{}, stress_zz{}, volume0{}, F[3][3];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) F[i][j] = Pack{} + (i == j ? Real(1) : Real(0));
        bool any = false;
        for (int q = 0; q < n; ++q) {
          const uint32_t p = g0 + uint32_t(q);
          if (!(ps.flags[p] & Particles::record_flag)) continue;
          any = true;
          record[q] = 1;
          stress_zz[q] = ps.stress[p][2];
          volume0[q] = ps.volume0[p];
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) F[i][j][q] = ps.deformation[p](i, j);
        }
        if (!any) continue;
        const Pack current_volume = record * determinant(F) * volume0;
        bucket_stress_volume += stress_zz * current_volume;
        bucket_volume += current_volume;
      }
    }
    Real bucket_sv = 0, bucket_v = 0;
    for (int q = 0; q < pack_width; ++q) bucket_sv += bucket_stress_volume[q], bucket_v += bucket_volume[q];
    rows.insert(rows.end(), {bucket_sv, bucket_v});
  }
  const auto sums = sim.domain().sum_in_order(bucket_order_keys(state.buckets.buckets()), rows, 2);
  const Real stress_volume = sums[0], volume = sums[1];
  return volume > 0 ? area_ * stress_volume / volume : 0;
}

namespace {
bool counts(const Simulation& sim, size_t p) {
  return sim.bodies()[size_t(sim.particles().body[p])].role == BodyRole::deformable && sim.particles().volume0[p] > 0;
}
}  // namespace

Real AverageStressForce::initial_cross_section(const Simulation& sim, const Vec3& axis) {
  const Particles& ps = sim.particles();
  const Vec3 a = axis.normalized();
  Real lo = std::numeric_limits<Real>::infinity(), hi = -lo, volume0 = 0;
  for (size_t p = 0; p < ps.size(); ++p) {
    if (!counts(sim, p)) continue;
    const Real along = ps.position[p].dot(a), reach = ps.half_size0[p].cast<Real>().dot(a.cwiseAbs());
    lo = std::min(lo, along - reach), hi = std::max(hi, along + reach);
    volume0 += ps.volume0[p];
  }
  return hi > lo ? volume0 / (hi - lo) : 0;
}

Real AverageStressForce::operator()(const Simulation& sim) const {
  const Particles& ps = sim.particles();
  const Vec3& a = axis_;
  // Point by point in the particles' order; with several processes in the one-process
  // order (bucket by bucket, Domain::sum_in_sequence). Before the first sort (no buckets)
  // the particles are one run in point order, on every process alike.
  const auto& buckets = sim.state().buckets.buckets();
  const bool sorted = !buckets.empty();
  std::vector<uint64_t> keys;
  std::vector<uint32_t> items;
  std::vector<Real> rows;
  auto add = [&](size_t begin, size_t end) {
    uint32_t count = 0;
    for (size_t p = begin; p < end; ++p) {
      if (!counts(sim, p)) continue;
      const Real along = a.dot(to_matrix(ps.stress[p]).cast<Real>() * a);
      const Real v = ps.deformation[p].cast<Real>().determinant() * ps.volume0[p];
      rows.insert(rows.end(), {along * v, v});
      ++count;
    }
    items.push_back(count);
  };
  if (sorted) {
    for (const Bucket& b : buckets) keys.push_back(bucket_order_key(b)), add(b.begin, b.end);
  } else {
    keys.push_back(0), add(0, ps.size());
  }
  const auto sums = sim.domain().sum_in_sequence(keys, items, rows, 2);
  const Real stress_volume = sums[0], volume = sums[1];
  return volume > 0 ? area_ * stress_volume / volume : 0;
}

}  // namespace latmpm::mpm
