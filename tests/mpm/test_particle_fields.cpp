// The particle field registry (particle_fields.hpp), material history (material_history.hpp)
// and the named-dataset checkpoint (checkpoint_io.hpp). The toy material below lives in this
// test only: it shows what a model with history declares and that the solver's per-pack
// update carries its variable (docs/architecture.md, "A material with history").
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <numeric>
#include <random>

#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "mpm/checkpoint_io.hpp"
#include "mpm/material_model.hpp"
#include "mpm/particle_fields.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
using namespace latmpm::mpm;

namespace {

// Linear elasticity plus one history variable: the accumulated volumetric strain
// e_v = ∫ tr D dt (explicit, like the stress), which for a constant L after n steps is
// exactly n dt tr L — the reference the test checks against.
struct ToyVolumetricMemory {
  static constexpr std::array<HistoryVariable, 1> history{{{"toy_volumetric_strain", 0.0}}};
  LinearElastic elastic;

  template <class T>
  void update_stress(const Deformation<T>& d, Stress<T>& s, T* h) const {
    elastic.update_stress(d, s);
    h[0] += d.dt * (d.velocity_gradient[0][0] + d.velocity_gradient[1][1] + d.velocity_gradient[2][2]);
  }
  template <class T>
  T strain_energy_density(const Deformation<T>& d, const Stress<T>& s, const T*) const {
    return elastic.strain_energy_density(d, s);
  }
  Real wave_speed_squared(Real j) const { return elastic.wave_speed_squared(j); }
};

std::string scratch_file(const std::string& stem) {
  return latmpm::test::process_scratch("particle-fields") / (stem + ".h5");
}

Particles numbered_particles(size_t n) {
  Particles ps;
  declare_history<ToyVolumetricMemory>(ps);
  ps.resize(n);
  for (size_t p = 0; p < n; ++p) {
    ps.position[p] = Vec3(Real(p), 2.0 * Real(p), -Real(p));
    ps.deformation[p](0, 1) = 1e-3 * Real(p);
    ps.stress[p][3] = 10.0 * Real(p);
    ps.id[p] = uint32_t(p);
    ps.body[p] = int32_t(p % 3);
    ps.flags[p] = uint8_t(p % 2);
    ps.history[0].values[p] = 0.5 * Real(p);
  }
  return ps;
}

}  // namespace

TEST_CASE("A history variable is declared once and sized, filled and sorted with every field", "[mpm][fields]") {
  Particles ps;
  const auto columns = declare_history<ToyVolumetricMemory>(ps);
  REQUIRE(columns == std::vector<uint32_t>{0});
  // A second body of the same model shares the column.
  CHECK(declare_history<ToyVolumetricMemory>(ps) == columns);
  CHECK(declare_history<NeoHookean>(ps).empty());
  ps.resize(5);
  REQUIRE(ps.history.size() == 1);
  CHECK(ps.history[0].values == std::vector<Real>(5, 0.0));
  CHECK(ps.contact_body.empty());  // optional fields stay off until the run needs them

  Particles sorted = numbered_particles(7);
  std::vector<uint32_t> order(7);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(3));
  sorted.permute(order);
  // Every field of a particle moved together: its id still names its values.
  for (size_t q = 0; q < 7; ++q) {
    const Real p = Real(sorted.id[q]);
    CHECK(sorted.position[q][1] == 2 * p);
    CHECK(sorted.stress[q][3] == 10 * p);
    CHECK(sorted.history[0].values[q] == 0.5 * p);
    CHECK(sorted.body[q] == int32_t(sorted.id[q] % 3));
  }
}

TEST_CASE("The solver's per-pack update carries a model's history variable", "[mpm][fields][material]") {
  MaterialParameters m;
  m.young_modulus = 1e6, m.poisson_ratio = 0.3, m.density = 1000;
  const ToyVolumetricMemory toy{LinearElastic::from(m, 1)};
  const Real dt = 1e-4;
  Mat3 L;
  L << 0.3, 0.1, 0, -0.1, -0.2, 0.05, 0, 0.02, 0.4;
  // Eight particles in one pack, as the gather kernel updates them.
  Deformation<Pack> d;
  d.dt = dt;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) d.velocity_gradient[r][c] = Pack{} + L(r, c), d.f_new[r][c] = Pack{} + (r == c);
  d.jacobian = Pack{} + 1;
  Pack s[6] = {}, h[1] = {};
  const int steps = 50;
  for (int n = 0; n < steps; ++n) update_material_stress(toy, d, s, h);
  for (int q = 0; q < pack_width; ++q) CHECK(h[0][q] == Approx(steps * dt * L.trace()).epsilon(1e-12));
  // The one-particle form the solver uses at set-up agrees with the pack.
  Real one = 0;
  SymTensor stress = SymTensor::Zero();
  for (int n = 0; n < steps; ++n) stress = updated_stress(toy, L, Mat3::Identity(), dt, stress, &one);
  CHECK(one == Approx(h[0][0]).epsilon(1e-14));
  CHECK(stress[0] == Approx(s[0][0]).epsilon(1e-12));
}

TEST_CASE("Every registered field comes back from a checkpoint by name", "[mpm][fields][checkpoint]") {
  const Particles saved = numbered_particles(9);
  const std::string path = scratch_file("latmpm-fields");
  {
    Hdf5File file(path, Hdf5File::Mode::create);
    CheckpointWriter out(file, "/state");
    CheckpointWriter particles = out.sub("particles");
    for_each_particle_field(saved, [&](const ParticleField& f, const auto& values, const auto&) {
      if (!(f.optional && values.empty())) particles.rows(f.name, values);
    });
    out.scalar("time", 0.25);
  }
  Particles loaded = numbered_particles(9);
  for (auto& x : loaded.position) x.setZero();
  for (auto& v : loaded.history[0].values) v = -1;
  {
    Hdf5File file(path, Hdf5File::Mode::read);
    const CheckpointReader in(file, "/state");
    CHECK(in.scalar("time") == 0.25);
    CHECK(file.exists("/state/particles/toy_volumetric_strain"));
    const CheckpointReader particles = in.sub("particles");
    for_each_particle_field(loaded, [&](const ParticleField& f, auto& values, const auto&) {
      if (f.optional && values.empty()) return;
      values = particles.rows<typename std::decay_t<decltype(values)>::value_type>(f.name, 9);
    });
    // A point set of another size is named as such, field and counts.
    CHECK_THROWS_WITH(particles.rows<Vec3>("position", 10), Catch::Contains("position") && Catch::Contains("9 rows"));
    CHECK_THROWS_WITH(in.scalar("nothing"), Catch::Contains("nothing") && Catch::Contains("missing"));
  }
  std::filesystem::remove(path);
  CHECK(loaded.position == saved.position);
  CHECK(loaded.history[0].values == saved.history[0].values);
  CHECK(loaded.id == saved.id);
  CHECK(loaded.flags == saved.flags);
}

TEST_CASE("A checkpoint of another format version is refused with its version named", "[mpm][fields][checkpoint]") {
  const std::string path = scratch_file("latmpm-format");
  {
    Hdf5File file(path, Hdf5File::Mode::create);
    file.write("/state/solver/scalars", std::vector<double>(18, 0.0), {18});  // format 1: positional
  }
  {
    Hdf5File file(path, Hdf5File::Mode::read);
    CHECK_THROWS_AS(CheckpointReader(file, "/state"), InputError);
    CHECK_THROWS_WITH(CheckpointReader(file, "/state"), Catch::Contains("format_version"));
  }
  {
    Hdf5File file(path, Hdf5File::Mode::read_write);
    file.set_attribute("/state", "format_version", int64_t(checkpoint_format_version + 1));
  }
  Hdf5File file(path, Hdf5File::Mode::read);
  CHECK_THROWS_WITH(CheckpointReader(file, "/state"), Catch::Contains("format " + std::to_string(checkpoint_format_version + 1)));
  std::filesystem::remove(path);
}

TEST_CASE("A checkpoint written by the other precision build is refused with both precisions named", "[mpm][fields][checkpoint]") {
  const std::string path = scratch_file("latmpm-precision");
  {
    Hdf5File file(path, Hdf5File::Mode::create);
    CheckpointWriter writer(file, "/state");  // stamps this build's format and precision
  }
  {
    Hdf5File file(path, Hdf5File::Mode::read);
    CHECK_NOTHROW(CheckpointReader(file, "/state"));
  }
  const std::string other = std::string(precision_name) == "double" ? "mixed" : "double";
  {
    Hdf5File file(path, Hdf5File::Mode::read_write);
    file.set_attribute("/state", "precision", other);
  }
  Hdf5File file(path, Hdf5File::Mode::read);
  CHECK_THROWS_AS(CheckpointReader(file, "/state"), InputError);
  CHECK_THROWS_WITH(CheckpointReader(file, "/state"), Catch::Contains(other + "-precision build") &&
                                                          Catch::Contains(std::string(precision_name) + "-precision one"));
  std::filesystem::remove(path);
}
