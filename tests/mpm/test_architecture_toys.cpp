// The extension points of docs/architecture.md, exercised by toys that live in this test
// only: a boundary with the hooks of boundary.hpp and an observer of the step. (The toy
// material with a history variable is in test_particle_fields.cpp.)
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>

#include "core/hdf5_file.hpp"
#include "mpm/boundary.hpp"
#include "mpm/checkpoint_io.hpp"
#include "mpm/simulation.hpp"
#include "mpm/sparse_grid.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {

// A toy boundary: a floor that stops every node with mass below the height z0 (no-slip),
// reaction Σ m (0 − v)/dt over those nodes.
struct ToyFloor {
  Real z0 = 0;
  Vec3 reaction = Vec3::Zero();

  void constrain(BoundaryPass& pass) {
    reaction = Vec3::Zero();
    for (size_t b = 0; b < pass.grid.block_count(); ++b) {
      const auto c = pass.grid.coord(b);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          for (int k = 0; k < 4; ++k) {
            Real* node = pass.grid.block(b) + SparseGrid::node_offset(i, j, k);
            const Vec3 x = SparseGrid::node_position(c[0] * 4 + i, c[1] * 4 + j, c[2] * 4 + k, pass.cell_size);
            if (!(node[lane::mass] > 0) || x[2] >= z0) continue;
            for (int a = 0; a < 3; ++a) {
              reaction[a] -= node[lane::mass] * node[lane::momentum + a] / pass.dt;
              node[lane::momentum + a] = 0;
            }
          }
    }
  }
  void impose(BoundaryPass&, int) {}
  void advance(const BoundaryPass&, BoundaryLedger&) {}
  void save(CheckpointWriter& out) const { out.rows("reaction", std::vector<Vec3>{reaction}); }
  void load(const CheckpointReader& in) { reaction = in.rows<Vec3>("reaction", 1)[0]; }
  BoundaryReport report() const {
    BoundaryReport r;
    r.name = "toy_floor";
    r.reaction = reaction;
    return r;
  }
};

// The set with the toy as one more alternative: all a new kind adds to the set.
using ToyBoundarySet = std::variant<PointBoundary, RigidBoundary, PenaltyBoundary, ToyFloor>;

}  // namespace

TEST_CASE("A toy boundary with the hooks joins the set and its reaction is the momentum it takes", "[mpm][boundary]") {
  static_assert(has_boundary_hooks<ToyFloor>::value);
  static_assert(!has_boundary_hooks<Vec3>::value);
  const Real h = 0.01, dt = 1e-3;
  SparseGrid grid;
  grid.set_active_blocks({SparseGrid::block_key(0, 0, 0)});
  for (int n = 0; n < SparseGrid::nodes_per_block; ++n)
    for (int l = 0; l < lane::count; ++l) grid.block(0)[n * lane::count + l] = 0;
  // Nodes of mass 2 kg moving at (1, 0, -3) m/s on the planes k = 0..3 (z = k h).
  Vec3 taken = Vec3::Zero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        Real* node = grid.node(i, j, k);
        node[lane::mass] = 2;
        node[lane::momentum] = 1, node[lane::momentum + 2] = -3;
        if (k < 2) taken += 2 * Vec3(1, 0, -3);
      }
  std::vector<ToyBoundarySet> set{ToyFloor{1.5 * h}};
  BoundaryPass pass{grid, h, dt, Vec3::Zero()};
  BoundaryLedger ledger;
  for (auto& b : set) std::visit([&](auto& boundary) { boundary.constrain(pass), boundary.advance(pass, ledger); }, b);
  const BoundaryReport r = std::visit([](const auto& boundary) { return boundary.report(); }, set[0]);
  CHECK((r.reaction + taken / dt).norm() <= 1e-12 * taken.norm() / dt);
  CHECK(grid.node(1, 1, 1)[lane::momentum + 2] == 0);
  CHECK(grid.node(1, 1, 2)[lane::momentum + 2] == -3);

  // Save and load through its own checkpoint group.
  const auto path = (std::filesystem::temp_directory_path() / ("latmpm-toy-" + std::to_string(::getpid()) + ".h5")).string();
  {
    Hdf5File file(path, Hdf5File::Mode::create);
    CheckpointWriter out = CheckpointWriter(file, "/state").sub("boundaries/toy");
    std::visit([&](const auto& boundary) { boundary.save(out); }, set[0]);
  }
  ToyBoundarySet restored{ToyFloor{}};
  {
    Hdf5File file(path, Hdf5File::Mode::read);
    const CheckpointReader in = CheckpointReader(file, "/state").sub("boundaries/toy");
    std::visit([&](auto& boundary) { boundary.load(in); }, restored);
  }
  std::filesystem::remove(path);
  CHECK(std::get<ToyFloor>(restored).reaction == r.reaction);
}

TEST_CASE("A toy observer sees every step and measures the kinetic energy the step reports", "[mpm][observer]") {
  const Real h = 1e-3;
  PointSet points = empty_point_set(h, 2);
  add_points(points, Vec3(0, 0, 0), Vec3(4 * h, 4 * h, 4 * h), "block");
  Settings s;
  s.cell_size = h;
  s.gravity = Vec3(0, 0, -9.81);
  Simulation sim(points, {deformable("block", elastic(1e6, 0.3, 1000))}, s);
  for (auto& v : sim.mutable_particles().velocity) v = ParticleVec3(0.1, 0, 0);
  // The toy observer: its own ½ Σ m v² over the particles after each step.
  struct Seen {
    int64_t step;
    Real time, measured, reported;
  };
  std::vector<Seen> seen;
  sim.add_observer([&](const Simulation& state, const StepDiagnostics& d) {
    Real kinetic = 0;
    const Particles& ps = state.particles();
    for (size_t p = 0; p < ps.size(); ++p) kinetic += 0.5 * ps.mass[p] * ps.velocity[p].squaredNorm();
    seen.push_back({d.step, d.time, kinetic, d.kinetic_energy});
  });
  for (int n = 0; n < 20; ++n) sim.step();
  REQUIRE(seen.size() == 20);
  for (size_t n = 0; n < seen.size(); ++n) {
    CHECK(seen[n].step == int64_t(n + 1));
    if (n > 0) CHECK(seen[n].time > seen[n - 1].time);
    CHECK(seen[n].measured == Approx(seen[n].reported).epsilon(1e-12));
  }
  // The block falls freely: gravity's work shows up as kinetic energy.
  CHECK(seen.back().measured > seen.front().measured);
}
