// Checkpoints of the solver state (Simulation::save_state / load_state): a simulation
// restored from a saved state continues exactly like the one that saved it.
#include <catch2/catch.hpp>

#include <hdf5.h>
#include <unistd.h>

#include <filesystem>
#include <random>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "mpm/material_model.hpp"
#include "mpm/simulation.hpp"
#include "point_builders.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
// A free rigid box of 10 g moving down at `speed` (m/s) onto the scene below it.
RigidBodySettings falling_flyer(const Vec3& box_min, const Vec3& box_max, Real speed) {
  RigidBodySettings flyer;
  flyer.name = "flyer";
  flyer.box_min = box_min;
  flyer.box_max = box_max;
  flyer.motion = RigidMotion::free;
  flyer.velocity = Vec3(0, 0, -speed);
  flyer.mass = 0.01;
  return flyer;
}

std::unique_ptr<Simulation> simulation_with(const PointSet& points, const std::vector<BodySettings>& bodies,
                                            const Settings& settings, const RigidBodySettings& rigid_body) {
  auto sim = std::make_unique<Simulation>(points, bodies, settings);
  sim->add_rigid_body(rigid_body);
  return sim;
}

// A block of points (cells of 1 mm) of one material under gravity, three steps on, saved as
// `path`: the scene of the tests that refuse a checkpoint.
struct SavedBlock {
  PointSet points;
  Settings settings;
  std::vector<BodySettings> bodies;
};
SavedBlock saved_block(const MaterialParameters& material, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                       const std::string& path) {
  const Real h = 1e-3;
  SavedBlock block{empty_point_set(h, 2), Settings{}, {deformable("block", material)}};
  add_points(block.points, h * lo, h * hi, "block");
  block.settings.cell_size = h;
  block.settings.gravity = Vec3(0, 0, -9.81);
  Simulation saved(block.points, block.bodies, block.settings);
  for (int n = 0; n < 3; ++n) saved.step();
  Hdf5File file(path, Hdf5File::Mode::create);
  saved.save_state(file, "/state");
  return block;
}

// Deletes a dataset from a checkpoint, as a version that did not write it would have left it.
void remove_dataset(const std::string& path, const std::string& dataset) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(file >= 0);
  CHECK(H5Ldelete(file, dataset.c_str(), H5P_DEFAULT) >= 0);
  H5Fclose(file);
}
}  // namespace

TEST_CASE("A simulation restored from its saved state continues bit for bit", "[mpm][checkpoint]") {
  const auto shape = GENERATE(ShapeFunctionKind::ugimp, ShapeFunctionKind::ddmp);
  // The reference-map filter keeps where every point started (Particles::reference_position),
  // which the checkpoint must carry: a pass every 7 steps, before and after the save.
  const auto filter = GENERATE(NullSpaceFilter::none, NullSpaceFilter::reference_map);
  CAPTURE(to_string(shape), to_string(filter));
  const Real h = 1e-3;
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(-5 * h, -3 * h, 0), Eigen::Vector3d(6 * h, 4 * h, 10 * h), "block");
  add_points(points, Eigen::Vector3d(-5 * h, -3 * h, -h), Eigen::Vector3d(6 * h, 4 * h, 0), "base");
  std::mt19937 rng(4);
  std::uniform_real_distribution<Real> u(-0.2, 0.2);
  for (auto& x : points.position) x += h * Eigen::Vector3d(u(rng), u(rng), u(rng));
  Settings s;
  s.cell_size = h;
  s.shape_function = shape;
  s.scheme = scheme_for(shape);
  s.gravity = Vec3(0, 0, -9.81);
  s.null_space_filter = filter;
  s.null_space_filter_every = 7;
  const std::vector<BodySettings> bodies = {
      deformable("block", filter == NullSpaceFilter::none ? elastic(1e6, 0.3, 1000)
                                                          : elastic(1e6, 0.3, 1000, MaterialKind::neo_hookean)),
                                            rigid("base", BodyRole::fixed, Vec3::Zero(), 1000)};
  const RigidBodySettings flyer = falling_flyer(Vec3(-5 * h, -3 * h, 10 * h), Vec3(6 * h, 4 * h, 12 * h), 2);
  auto make = [&] { return simulation_with(points, bodies, s, flyer); };
  auto state_of = [](const Simulation& sim) {
    std::vector<Real> v;
    const Particles& ps = sim.particles();
    for (size_t p = 0; p < ps.size(); ++p) {
      v.push_back(ps.id[p]);
      for (int a = 0; a < 3; ++a) v.push_back(ps.position[p][a]), v.push_back(ps.velocity[p][a]);
      for (int c = 0; c < 6; ++c) v.push_back(ps.stress[p][c]);
    }
    const auto& d = sim.last_diagnostics();
    v.insert(v.end(), {d.time, d.dt, d.kinetic_energy, d.strain_energy, d.external_work, d.energy_error,
                       d.reaction[1][2], d.rigid[0].velocity[2], d.rigid[0].displacement[2]});
    return v;
  };
  const latmpm::test::ScratchDir scratch("checkpoint-state");
  const std::filesystem::path path = scratch / "state.h5";
  auto first = make();
  for (int n = 0; n < 30; ++n) first->step();
  {
    Hdf5File file(path.string(), Hdf5File::Mode::create);
    first->save_state(file, "/state");
  }
  auto second = make();
  {
    Hdf5File file(path.string(), Hdf5File::Mode::read);
    second->load_state(file, "/state");
  }
  std::filesystem::remove(path);
  REQUIRE(second->step_count() == 30);
  CHECK(state_of(*second) == state_of(*first));
  for (int n = 0; n < 30; ++n) first->step(), second->step();
  const auto a = state_of(*first), b = state_of(*second);
  REQUIRE(a.size() == b.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
  INFO("shape " << to_string(shape));
  CHECK(differing == 0);
  CHECK(first->last_diagnostics().kinetic_energy > 0);
}

TEST_CASE("A checkpoint without the linear elastic stress work resumes from the complementary energy",
          "[mpm][checkpoint][material]") {
  // Checkpoints written before the column existed (2026-11-27) lack it: the run resumes
  // with each point's stress work set to its complementary energy ½ σ:C⁻¹σ J (the energy
  // that run reported; linear_elastic.hpp), moves exactly as it would have, and its strain
  // energy differs from the uninterrupted run's by what the two measures differed at the save.
  const Real h = 1e-3;
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(-3 * h, -3 * h, 0), Eigen::Vector3d(3 * h, 3 * h, 8 * h), "block");
  add_points(points, Eigen::Vector3d(-3 * h, -3 * h, -h), Eigen::Vector3d(3 * h, 3 * h, 0), "base");
  Settings s;
  s.cell_size = h;
  const MaterialParameters material = elastic(1e6, 0.3, 1000);
  const std::vector<BodySettings> bodies = {deformable("block", material),
                                            rigid("base", BodyRole::fixed, Vec3::Zero(), 1000)};
  // 20 m/s squeezes the block by tens of per cent.
  const RigidBodySettings flyer = falling_flyer(Vec3(-3 * h, -3 * h, 8 * h), Vec3(3 * h, 3 * h, 10 * h), 20);
  auto make = [&] { return simulation_with(points, bodies, s, flyer); };
  const std::string column = "linear_elastic_stress_work";
  auto first = make();
  for (int n = 0; n < 200; ++n) first->step();
  const Particles& saved = first->particles();
  REQUIRE(saved.history_column(column) != nullptr);
  const LinearElastic model = LinearElastic::from(material, 1);
  Real work = 0, complementary = 0;
  for (size_t p = 0; p < saved.size(); ++p) {
    if (saved.body[p] != 0) continue;
    work += saved.volume0[p] * saved.history_column(column)->values[p];
    complementary += saved.volume0[p] * strain_energy_density(model, saved.deformation[p].cast<Real>(),
                                                               saved.stress[p].cast<Real>());
  }
  INFO("stress work " << work << " J, complementary energy " << complementary << " J");
  REQUIRE(work == Approx(first->last_diagnostics().strain_energy).epsilon(1e-12));
  REQUIRE(std::abs(work - complementary) > 1e-3 * work);  // the two measures differ here

  const latmpm::test::ScratchDir scratch("checkpoint-stress-work");
  const std::string path = scratch / "state.h5";
  {
    Hdf5File file(path, Hdf5File::Mode::create);
    first->save_state(file, "/state");
  }
  remove_dataset(path, "/state/particles/" + column);  // as an older version wrote it
  auto second = make();
  {
    Hdf5File file(path, Hdf5File::Mode::read);
    REQUIRE_NOTHROW(second->load_state(file, "/state"));
  }
  for (int n = 0; n < 20; ++n) first->step(), second->step();
  const Particles &a = first->particles(), &b = second->particles();
  REQUIRE(a.size() == b.size());
  size_t moved_differently = 0;
  for (size_t p = 0; p < a.size(); ++p) moved_differently += a.position[p] != b.position[p] || a.stress[p] != b.stress[p];
  CHECK(moved_differently == 0);
  CHECK(second->last_diagnostics().strain_energy ==
        Approx(first->last_diagnostics().strain_energy - (work - complementary)).epsilon(1e-12));
}

TEST_CASE("A checkpoint without a history column that cannot be derived is refused, naming it",
          "[mpm][checkpoint][material]") {
  // J2's plastic strain is path history: no state gives it back (unlike the linear elastic
  // stress work above), so such a checkpoint must not resume.
  const latmpm::test::ScratchDir scratch("checkpoint-j2-history");
  const std::string path = scratch / "state.h5";
  const SavedBlock block = saved_block(j2_material(steel_42crmo4_400c(), 7850), {-2, -2, 0}, {2, 2, 4}, path);
  remove_dataset(path, "/state/particles/j2_alpha");
  Simulation restored(block.points, block.bodies, block.settings);
  Hdf5File file(path, Hdf5File::Mode::read);
  CHECK_THROWS_AS(restored.load_state(file, "/state"), InputError);
  CHECK_THROWS_WITH(restored.load_state(file, "/state"), Catch::Contains("j2_alpha") && Catch::Contains("missing"));
}

TEST_CASE("A checkpoint whose buckets do not hold each particle once, in bucket order, is refused",
          "[mpm][checkpoint]") {
  // Several MPI processes cut the bucket table and keep their buckets' particles by its
  // ranges: a table that tiles the particles but out of order, or whose runs stray into the
  // next bucket, would give a particle to two processes or to none (docs/cluster.md).
  const latmpm::test::ScratchDir scratch("checkpoint-buckets");
  const std::string path = scratch / "state.h5";
  const std::string table = "/state/buckets/buckets";
  const auto [points, s, bodies] = saved_block(elastic(1e6, 0.3, 1000), {-5, -3, 0}, {6, 4, 10}, path);
  std::vector<size_t> dims;
  const std::vector<int64_t> rows = Hdf5File(path, Hdf5File::Mode::read).read_int64(table, &dims);
  REQUIRE(dims.size() == 2);
  REQUIRE(dims[0] >= 2);  // two buckets at least
  auto refused_with = [&](const std::vector<int64_t>& tampered, const std::string& message) {
    {
      Hdf5File file(path, Hdf5File::Mode::read_write);
      file.write(table, tampered, dims);
    }
    Simulation restored(points, bodies, s);
    Hdf5File file(path, Hdf5File::Mode::read);
    CHECK_THROWS_AS(restored.load_state(file, "/state"), InputError);
    CHECK_THROWS_WITH(restored.load_state(file, "/state"), Catch::Contains(table) && Catch::Contains(message));
  };
  {  // the untampered table loads
    Simulation restored(points, bodies, s);
    Hdf5File file(path, Hdf5File::Mode::read);
    CHECK_NOTHROW(restored.load_state(file, "/state"));
  }
  std::vector<int64_t> swapped = rows;  // the first two buckets' coordinates exchanged
  for (int a = 0; a < 3; ++a) std::swap(swapped[size_t(a)], swapped[size_t(7 + a)]);
  refused_with(swapped, "is not after the previous one in bucket order");
  std::vector<int64_t> straying = rows;  // the first bucket takes the second one's first run
  ++straying[6], ++straying[7 + 5];
  refused_with(straying, "do not cover exactly its particles");
}
