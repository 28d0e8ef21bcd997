// Saving and restoring a Simulation's state for checkpoints. The particles are stored in
// their internal (bucket-sorted) order together with the buckets and runs, so a restored run
// scatters and gathers in exactly the order the uninterrupted one would: results agree bit
// for bit (the thread count does not matter, simulation_impl.hpp).
#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "mpm/simulation.hpp"
#include "mpm/simulation_impl.hpp"

namespace latmpm::mpm {

namespace {
template <class V, int N>
std::vector<double> flatten(const std::vector<V>& v) {
  std::vector<double> out;
  out.reserve(v.size() * N);
  for (const auto& x : v)
    for (int i = 0; i < N; ++i) out.push_back(x.data()[i]);
  return out;
}
template <class V, int N>
std::vector<V> unflatten(const std::vector<double>& d) {
  std::vector<V> out(d.size() / N);
  for (size_t p = 0; p < out.size(); ++p)
    for (int i = 0; i < N; ++i) out[p].data()[i] = d[p * N + i];
  return out;
}
std::vector<double> vec3s(const std::vector<RigidBodyState>& s, Vec3 RigidBodyState::*field) {
  std::vector<double> out;
  for (const auto& r : s)
    for (int a = 0; a < 3; ++a) out.push_back((r.*field)[a]);
  return out;
}
}  // namespace

void Simulation::save_state(Hdf5File& f, const std::string& g) const {
  const Particles& p = particles_;
  const size_t n = p.size();
  std::vector<std::string> names;
  for (const auto& b : bodies_) names.push_back(b.name);
  f.write_strings(g + "/bodies", names);
  names.clear();
  for (const auto& b : rigid_bodies_) names.push_back(b.name);
  if (!names.empty()) f.write_strings(g + "/rigid_bodies", names);
  f.write(g + "/particles/position", flatten<Vec3, 3>(p.position), {n, 3});
  f.write(g + "/particles/velocity", flatten<Vec3, 3>(p.velocity), {n, 3});
  f.write(g + "/particles/mass", p.mass, {n});
  f.write(g + "/particles/volume0", p.volume0, {n});
  f.write(g + "/particles/deformation", flatten<Mat3, 9>(p.deformation), {n, 9});
  f.write(g + "/particles/stress", flatten<SymTensor, 6>(p.stress), {n, 6});
  f.write(g + "/particles/half_size0", flatten<Vec3, 3>(p.half_size0), {n, 3});
  f.write(g + "/particles/body", p.body, {n});
  f.write(g + "/particles/id", std::vector<int64_t>(p.id.begin(), p.id.end()), {n});
  f.write(g + "/particles/flags", p.flags, {n});
  if (!p.contact_body.empty()) {  // penalty contact history (rigid_contact.hpp)
    f.write(g + "/particles/contact_body", p.contact_body, {n});
    f.write(g + "/particles/contact_anchor", flatten<Vec3, 3>(p.contact_anchor), {n, 3});
  }

  const auto& im = *impl_;
  std::vector<int64_t> buckets, runs;
  for (const auto& b : im.buckets.buckets())
    buckets.insert(buckets.end(), {b.coord[0], b.coord[1], b.coord[2], b.begin, b.end, b.run_begin, b.run_end});
  for (const auto& r : im.buckets.runs()) runs.insert(runs.end(), {r.body, r.begin, r.end});
  f.write(g + "/buckets/buckets", buckets, {buckets.size() / 7, 7});
  f.write(g + "/buckets/runs", runs, {runs.size() / 3, 3});
  f.set_attribute(g + "/buckets/buckets", "needs_sort", int64_t(im.needs_sort));

  const StepDiagnostics& d = diagnostics_;
  const size_t nb = bodies_.size(), nr = rigid_bodies_.size();
  f.write(g + "/solver/body_displacement", flatten<Vec3, 3>(d.body_displacement), {nb, 3});
  f.write(g + "/solver/reaction", flatten<Vec3, 3>(d.reaction), {nb, 3});
  f.write(g + "/solver/initial_centre", flatten<Vec3, 3>(im.initial_centre), {im.initial_centre.size(), 3});
  f.write(g + "/solver/scalars",
          std::vector<double>{double(d.step), d.time, d.dt, d.stable_dt, d.record_force, d.kinetic_energy,
                              d.strain_energy, d.external_work, d.max_speed, d.constraint_work, d.gravity_work,
                              d.rigid_energy, d.energy_error, im.max_speed, im.max_wave_speed, im.initial_energy,
                              initial_rigid_energy_, driven_rigid_work_},
          {18});
  f.write(g + "/rigid/displacement", vec3s(rigid_states_, &RigidBodyState::displacement), {nr, 3});
  f.write(g + "/rigid/velocity", vec3s(rigid_states_, &RigidBodyState::velocity), {nr, 3});
  f.write(g + "/rigid/reaction", vec3s(rigid_states_, &RigidBodyState::reaction), {nr, 3});
  std::vector<double> work;
  for (const auto& r : rigid_states_) work.push_back(r.work);
  f.write(g + "/rigid/work", work, {nr});
}

void Simulation::load_state(const Hdf5File& f, const std::string& g) {
  auto& im = *impl_;
  const size_t n = particles_.size();
  auto expect = [&](const std::string& dataset, size_t rows) {
    const auto dims = f.shape(g + dataset);
    if (dims.empty() || dims[0] != rows)
      throw InputError(f.path(), g + dataset,
                       "has " + std::to_string(dims.empty() ? 0 : dims[0]) + " rows where the scene gives " +
                           std::to_string(rows) + ": the checkpoint belongs to another scene or point set");
  };
  expect("/particles/position", n);
  std::vector<std::string> names;
  for (const auto& b : bodies_) names.push_back(b.name);
  if (f.read_strings(g + "/bodies") != names)
    throw InputError(f.path(), g + "/bodies", "the checkpoint's bodies differ from the scene's (another scene?)");
  names.clear();
  for (const auto& b : rigid_bodies_) names.push_back(b.name);
  if (!names.empty() && (!f.exists(g + "/rigid_bodies") || f.read_strings(g + "/rigid_bodies") != names))
    throw InputError(f.path(), g + "/rigid_bodies", "the checkpoint's rigid bodies differ from the scene's");
  expect("/solver/reaction", bodies_.size());
  expect("/rigid/velocity", rigid_bodies_.size());
  Particles& p = particles_;
  p.position = unflatten<Vec3, 3>(f.read_doubles(g + "/particles/position"));
  p.velocity = unflatten<Vec3, 3>(f.read_doubles(g + "/particles/velocity"));
  p.mass = f.read_doubles(g + "/particles/mass");
  p.volume0 = f.read_doubles(g + "/particles/volume0");
  p.deformation = unflatten<Mat3, 9>(f.read_doubles(g + "/particles/deformation"));
  p.stress = unflatten<SymTensor, 6>(f.read_doubles(g + "/particles/stress"));
  p.half_size0 = unflatten<Vec3, 3>(f.read_doubles(g + "/particles/half_size0"));
  p.body = f.read_int32(g + "/particles/body");
  const auto ids = f.read_int64(g + "/particles/id");
  p.id.assign(ids.begin(), ids.end());
  p.flags = f.read_uint8(g + "/particles/flags");
  if (!p.contact_body.empty()) {
    if (!f.exists(g + "/particles/contact_body"))
      throw InputError(f.path(), g + "/particles/contact_body",
                       "missing: the scene has a penalty-contact rigid body, the checkpoint's run had none");
    p.contact_body = f.read_int32(g + "/particles/contact_body");
    p.contact_anchor = unflatten<Vec3, 3>(f.read_doubles(g + "/particles/contact_anchor"));
  }

  const auto b = f.read_int64(g + "/buckets/buckets");
  const auto r = f.read_int64(g + "/buckets/runs");
  std::vector<Bucket> buckets(b.size() / 7);
  for (size_t i = 0; i < buckets.size(); ++i) {
    const int64_t* x = &b[7 * i];
    buckets[i].coord = {int(x[0]), int(x[1]), int(x[2])};
    buckets[i].begin = uint32_t(x[3]), buckets[i].end = uint32_t(x[4]);
    buckets[i].run_begin = uint32_t(x[5]), buckets[i].run_end = uint32_t(x[6]);
  }
  std::vector<BodyRun> runs(r.size() / 3);
  for (size_t i = 0; i < runs.size(); ++i) runs[i] = {int32_t(r[3 * i]), uint32_t(r[3 * i + 1]), uint32_t(r[3 * i + 2])};
  im.buckets.restore(std::move(buckets), std::move(runs));
  im.needs_sort = f.int_attribute(g + "/buckets/buckets", "needs_sort") != 0;
  if (!im.needs_sort) im.compute_boxes_from_positions();

  StepDiagnostics& d = diagnostics_;
  d.body_displacement = unflatten<Vec3, 3>(f.read_doubles(g + "/solver/body_displacement"));
  d.reaction = unflatten<Vec3, 3>(f.read_doubles(g + "/solver/reaction"));
  im.initial_centre = unflatten<Vec3, 3>(f.read_doubles(g + "/solver/initial_centre"));
  const auto s = f.read_doubles(g + "/solver/scalars");
  if (s.size() != 18) throw InputError(f.path(), g + "/solver/scalars", "expected 18 values");
  d.step = int64_t(s[0]), d.time = s[1], d.dt = s[2], d.stable_dt = s[3], d.record_force = s[4];
  d.kinetic_energy = s[5], d.strain_energy = s[6], d.external_work = s[7], d.max_speed = s[8];
  d.constraint_work = s[9], d.gravity_work = s[10], d.rigid_energy = s[11], d.energy_error = s[12];
  im.max_speed = s[13], im.max_wave_speed = s[14], im.initial_energy = s[15];
  initial_rigid_energy_ = s[16], driven_rigid_work_ = s[17];
  im.refresh_needed = false;

  const auto disp = unflatten<Vec3, 3>(f.read_doubles(g + "/rigid/displacement"));
  const auto vel = unflatten<Vec3, 3>(f.read_doubles(g + "/rigid/velocity"));
  const auto reac = unflatten<Vec3, 3>(f.read_doubles(g + "/rigid/reaction"));
  const auto work = f.read_doubles(g + "/rigid/work");
  for (size_t k = 0; k < rigid_states_.size(); ++k)
    rigid_states_[k] = {disp[k], vel[k], reac[k], work[k]};
  d.rigid = rigid_states_;
}

}  // namespace latmpm::mpm
