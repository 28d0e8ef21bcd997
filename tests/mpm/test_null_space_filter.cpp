// The null-space filter on F (null_space_filter.hpp; Gritton, Berzins & Kirby 2017). The
// references: what a least-squares projection onto the gradients of the grid's fields must
// do whatever the code (give back every such gradient; keep the mass-weighted sum, since
// constants are gradients of linear fields; change nothing on a second pass), and the
// state of a body whose points hold a strain their positions do not show: its equilibrium is
// the undeformed body, strain energy zero.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "core/errors.hpp"
#include "mpm/material_model.hpp"
#include "mpm/null_space_filter.hpp"
#include "mpm/simulation.hpp"
#include "point_builders.hpp"

using namespace latmpm;
using namespace latmpm::mpm;
using namespace latmpm::mpm::test;

namespace {
constexpr Real h = 1e-3, side = 4e-3, E = 113.8e9, nu = 0.342, rho = 4430;

MaterialParameters titanium() { return elastic(E, nu, rho, MaterialKind::neo_hookean); }

// A 4 mm neo-Hookean Ti-6Al-4V block, 2 points per 1 mm cell per direction, sitting one cell
// off the grid's origin.
Simulation block(ShapeFunctionKind shape, NullSpaceFilter filter) {
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(h, h, h), Eigen::Vector3d(h + side, h + side, h + side), "block");
  Settings s;
  s.cell_size = h;
  s.shape_function = shape;
  s.flip_blend = 1;
  // MUSL: its balance has no projection term (docs/solver.md, "Energy"), so what
  // transfer_dissipation holds is the filter's loss alone.
  s.scheme = UpdateScheme::musl;
  s.null_space_filter = filter;
  s.threads = 1;
  return Simulation(points, {deformable("block", titanium())}, s);
}

// The shapes whose stencils the filter takes (CPDI1 is refused; cpGIMP and B-spline 3 are
// uGIMP's and B-spline 2's kin).
const std::vector<ShapeFunctionKind> tensor_product_shapes{ShapeFunctionKind::linear, ShapeFunctionKind::ugimp,
                                                           ShapeFunctionKind::bspline2, ShapeFunctionKind::ddmp};

// The indices of every point of ps, for project_onto_grid_gradients.
std::vector<uint32_t> every_point(const Particles& ps) {
  std::vector<uint32_t> points(ps.size());
  for (size_t p = 0; p < ps.size(); ++p) points[p] = uint32_t(p);
  return points;
}

// max |after − before| over every component, relative to max |before|.
Real largest_change(const PointValues& before, const PointValues& after) {
  Real change = 0, size = 0;
  for (size_t p = 0; p < before.size(); ++p)
    for (int k = 0; k < 9; ++k)
      change = std::max(change, std::abs(after[p][k] - before[p][k])), size = std::max(size, std::abs(before[p][k]));
  return change / size;
}

// Sets every point's F (and the stress that goes with it) from f(x_p); returns the strain
// energy Σ V0 ψ(F_p) (Bonet & Wood's neo-Hookean energy, neo_hookean.hpp), J.
template <class Field>
Real set_deformation(Simulation& sim, Field f) {
  Particles& ps = sim.mutable_particles();
  const NeoHookean model = NeoHookean::from(titanium(), 1);
  Real energy = 0;
  for (size_t p = 0; p < ps.size(); ++p) {
    const Mat3 F = f(ps.position[p]);
    ps.deformation[p] = F.cast<ParticleReal>();
    const SymTensor s = updated_stress(model, Mat3::Zero(), F, 0, SymTensor::Zero());
    for (int k = 0; k < 6; ++k) ps.stress[p][k] = ParticleReal(s[k]);
    energy += ps.volume0[p] * strain_energy_density(model, F, s);
  }
  return energy;
}
}  // namespace

TEST_CASE("The null-space filter keeps the grid's gradients and the mass-weighted sum, and is a projection",
          "[mpm][filter]") {
  const ShapeFunctionKind shape = GENERATE(from_range(tensor_product_shapes));
  CAPTURE(to_string(shape));
  const Simulation sim = block(shape, NullSpaceFilter::none);
  const Particles& ps = sim.particles();
  const std::vector<uint32_t> points = every_point(ps);
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-1, 1);

  // X_a(x) = c_a + A_a·x + B_a xyz: every shape reproduces the linear part; the linear
  // (trilinear) shape also xyz, trilinear in every cell. Their gradients must come back.
  const bool trilinear = shape == ShapeFunctionKind::linear;
  std::array<Vec3, 3> A;
  Vec3 B;
  for (int a = 0; a < 3; ++a) A[a] = Vec3(u(rng), u(rng), u(rng)), B[a] = trilinear ? u(rng) / (h * h) : 0;
  PointValues gradient(ps.size());
  for (size_t p = 0; p < ps.size(); ++p) {
    const Vec3& x = ps.position[p];
    const Vec3 xyz(x[1] * x[2], x[0] * x[2], x[0] * x[1]);  // ∇(xyz)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) gradient[p][3 * a + b] = A[a][b] + B[a] * xyz[b];
  }
  PointValues fitted = gradient;
  project_onto_grid_gradients(ps, points, shape, h, fitted);
  CHECK(largest_change(gradient, fitted) < 1e-7);

  // Random tensors: the mass-weighted sum is kept, a second pass changes nothing, and most
  // of them goes (8 points per node: point-to-point noise is mostly what no gradient holds).
  PointValues noise(ps.size());
  for (auto& row : noise)
    for (Real& v : row) v = u(rng);
  PointValues once = noise;
  project_onto_grid_gradients(ps, points, shape, h, once);
  std::array<Real, 9> before{}, after{};
  Real total_mass = 0;
  for (size_t p = 0; p < ps.size(); ++p) {
    total_mass += ps.mass[p];
    for (int k = 0; k < 9; ++k) before[k] += ps.mass[p] * noise[p][k], after[k] += ps.mass[p] * once[p][k];
  }
  for (int k = 0; k < 9; ++k) CHECK(std::abs(after[k] - before[k]) <= 1e-12 * total_mass);
  PointValues twice = once;
  project_onto_grid_gradients(ps, points, shape, h, twice);
  CHECK(largest_change(once, twice) < 1e-5);  // B-splines: 6e-6 (nodes of tiny mass at the support's edge)
  Real removed = 0, total = 0;
  for (size_t p = 0; p < ps.size(); ++p)
    for (int k = 0; k < 9; ++k)
      removed += ps.mass[p] * std::pow(noise[p][k] - once[p][k], 2), total += ps.mass[p] * std::pow(noise[p][k], 2);
  CHECK(removed > 0.5 * total);
}

TEST_CASE("A strain the grid cannot see stays in a free block without the null-space filter and leaves it with the filter",
          "[mpm][filter][energy]") {
  // F = I + ε s_p e_x⊗e_x with s_p = ±1 alternating from point to point along x: the
  // positions show no strain, so the free block's equilibrium is the undeformed one (strain
  // energy 0). Each cell holds one point of either sign, so the nodal forces of the
  // pattern's stress nearly cancel (exactly, to first order in ε, for gradients constant
  // along x within a cell): the grid barely sees it.
  const Real eps = 1e-3, spacing = h / 2;
  auto alternating = [&](const Vec3& x) {
    const int i = int(std::floor(x[0] / spacing));
    Mat3 F = Mat3::Identity();
    F(0, 0) += (i % 2 == 0 ? eps : -eps);
    return F;
  };
  const Real c = std::sqrt(elastic(E, nu, rho).p_wave_modulus() / rho);
  const Real end = 4 * side / c;  // two round trips of a wave through the block
  auto run = [&](NullSpaceFilter filter) {
    Simulation sim = block(ShapeFunctionKind::ugimp, filter);
    const Real initial = set_deformation(sim, alternating);
    sim.run_until(end);
    return std::make_pair(initial, sim.last_diagnostics());
  };
  const auto [initial_off, off] = run(NullSpaceFilter::none);
  // Measured: without the filter 98.6 % of the energy is still strain at the end (the balance
  // closes to 0.3 %).
  CHECK(off.strain_energy > 0.95 * initial_off);
  const NullSpaceFilter filter = GENERATE(NullSpaceFilter::deformation, NullSpaceFilter::reference_map);
  CAPTURE(to_string(filter));
  const auto [initial_on, on] = run(filter);
  // Measured: with the filter 7.1 % is left as strain and motion (deformation; 8.3 % with
  // reference_map: the first step's nodal forces come before the filter's first pass, which
  // follows each step).
  CHECK(on.strain_energy + on.kinetic_energy < 0.1 * initial_on);
  // The filter's loss, booked in transfer_dissipation, closes the balance (measured 0.48 %;
  // reference_map 0.74 %).
  CHECK(std::abs(on.energy_error) < 0.01 * initial_on);
}

TEST_CASE("The reference-map filter fits F to the points' start and keeps an F that their positions show",
          "[mpm][filter]") {
  const ShapeFunctionKind shape = GENERATE(from_range(tensor_product_shapes));
  CAPTURE(to_string(shape));
  const Simulation sim = block(shape, NullSpaceFilter::none);
  const Particles& ps = sim.particles();
  auto rows = [&](const Mat3& m) {
    std::array<Real, 9> row;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) row[3 * a + b] = m(a, b);
    return PointValues(ps.size(), row);
  };
  // Positions x = B X + c, an affine motion (a stretch, a shear and a turn), and F = B: the
  // map back, X = B⁻¹ (x − c), is a grid field, so F⁻¹ = B⁻¹ must come back.
  const Mat3 B = Eigen::AngleAxis<Real>(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix() *
                 (Mat3() << 1.02, 0.01, 0, 0, 0.97, 0.02, 0, 0, 1.01).finished();
  const Vec3 c(1e-4, -2e-4, 3e-4);
  std::vector<Vec3> started(ps.size());
  for (size_t p = 0; p < ps.size(); ++p) started[p] = B.inverse() * (ps.position[p] - c);
  const PointValues affine = rows(B.inverse());
  const std::vector<uint32_t> points = every_point(ps);
  PointValues fitted = affine;
  project_onto_grid_gradients(ps, points, shape, h, fitted, &started);
  CHECK(largest_change(affine, fitted) < 1e-7);

  // F = I + 0.01 e_x⊗e_x at every point while the positions are where the points started: a
  // drift of F that every grid gradient holds (the F-only filter keeps it: the test above). The
  // anchored fit takes it back toward the positions' I, most of it in the body's interior on
  // the first pass, and repeated passes converge to it (their fixed point is the map that
  // fits the starts).
  for (size_t p = 0; p < ps.size(); ++p) started[p] = ps.position[p];
  Mat3 drifted = Mat3::Identity();
  drifted(0, 0) = 1.01;
  PointValues values = rows(drifted.inverse());
  auto drift_left = [&](const PointValues& v) {  // mass-weighted mean |F⁻¹ − I|, over the first pass's
    Real sum = 0, mass = 0;
    for (size_t p = 0; p < ps.size(); ++p) {
      Real square = 0;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) square += std::pow(v[p][3 * a + b] - (a == b ? 1 : 0), 2);
      sum += ps.mass[p] * std::sqrt(square), mass += ps.mass[p];
    }
    return sum / mass;
  };
  const Real before = drift_left(values);
  project_onto_grid_gradients(ps, points, shape, h, values, &started);
  const Real once = drift_left(values);
  for (int pass = 1; pass < 10; ++pass) project_onto_grid_gradients(ps, points, shape, h, values, &started);
  const Real ten = drift_left(values);
  for (int pass = 10; pass < 30; ++pass) project_onto_grid_gradients(ps, points, shape, h, values, &started);
  const Real thirty = drift_left(values);
  CAPTURE(before, once, ten, thirty);
  // Measured: 47 % left after one pass (50 % with bspline2), 1.7 % after 30. B-spline 2
  // stalls at 23–24 % after 10 passes: its nodes at the support's edge carry tiny weights
  // against their gradients, so the anchors barely reach them.
  CHECK(once < 0.6 * before);
  CHECK(ten < once);
  if (shape == ShapeFunctionKind::bspline2) {
    CHECK(thirty < 0.5 * before);
  } else {
    CHECK(thirty < ten);
    CHECK(thirty < 0.05 * before);
  }
}

TEST_CASE("The null-space filter leaves the points next to a rigid surface that presses the body as the step made them",
          "[mpm][filter][rigid]") {
  // The alternating strain of the test above in a block over a fixed plane. One step with the
  // filter and one without start alike, and the filter is the step's last stage. Pressed, the
  // points whose cube of half-width 1.5 h reaches the plane must come out of both runs with the
  // same F, bit for bit, and the points above them lose the pattern; not pressed, every point
  // is filtered, those within 1.5 h of the plane included. A penalty plane presses while a
  // point touches it: 0.01 h above the block's bottom face (the bottom layer's domains overlap
  // it; centres 0.24, 0.74, 1.24 h from it: three layers in the band) and not half a cell below
  // the face (0.75, 1.25 h: two layers). A no-slip plane presses while a point's domain comes
  // within a cell of it: at the face (0.25, 0.75, 1.25 h: three layers) and not 1.1 cells
  // below it (1.35 h: one layer).
  const Real eps = 1e-3, spacing = h / 2;
  auto alternating = [&](const Vec3& x) {
    Mat3 F = Mat3::Identity();
    F(0, 0) += (int(std::floor(x[0] / spacing)) % 2 == 0 ? eps : -eps);
    return F;
  };
  struct Scene {
    RigidCoupling coupling;
    Real plane;  // m, the plane's height; the block's bottom face is at z = h
    bool pressed;
    int layers_in_band;
  };
  const Scene scene = GENERATE(Scene{RigidCoupling::penalty, 1.01 * h, true, 3},
                               Scene{RigidCoupling::penalty, 0.5 * h, false, 2},
                               Scene{RigidCoupling::no_slip, 1.0 * h, true, 3},
                               Scene{RigidCoupling::no_slip, -0.1 * h, false, 1});
  CAPTURE(to_string(scene.coupling), scene.plane);
  RigidBodySettings floor;
  floor.name = "floor";
  floor.motion = RigidMotion::fixed;
  floor.shape = RigidShape::half_space;
  floor.plane_point = Vec3(0, 0, scene.plane);
  floor.plane_normal = Vec3::UnitZ();
  floor.coupling = scene.coupling;
  Simulation off = block(ShapeFunctionKind::ugimp, NullSpaceFilter::none);
  Simulation on = block(ShapeFunctionKind::ugimp, NullSpaceFilter::deformation);
  for (Simulation* sim : {&off, &on}) {
    sim->add_rigid_body(floor);
    set_deformation(*sim, alternating);
    sim->step();
  }
  const Particles &a = off.particles(), &b = on.particles();
  REQUIRE(a.size() == b.size());
  CHECK(rigid_body_presses(on.rigid_bodies()[0], on.rigid_states()[0], 0, b, 0, h) == scene.pressed);
  int in_band = 0, kept = 0;
  Real pattern_left = 0;
  for (size_t p = 0; p < a.size(); ++p) {
    REQUIRE(a.id[p] == b.id[p]);
    const bool near = b.position[p][2] - scene.plane < 1.5 * h;
    CHECK(near_rigid_surface(on.rigid_bodies()[0], on.rigid_states()[0], b.position[p], h) == near);
    in_band += near;
    if (scene.pressed && near) {
      kept += b.deformation[p] == a.deformation[p];
    } else if (b.position[p][0] > 2 * h && b.position[p][0] < 4 * h) {
      // Away from the block's sides in x (in the cells next to them the edge nodes, which
      // the points reach only with their domains' ends, let the grid's fields follow the
      // pattern: it is not in the null space there, with or without the plane).
      pattern_left = std::max(pattern_left, std::abs(Real(b.deformation[p](0, 0)) - 1));
    }
  }
  CHECK(in_band == scene.layers_in_band * 8 * 8);
  CHECK(kept == (scene.pressed ? in_band : 0));
  // Measured: |F_xx − 1| ≤ 1.0e-6 left (0.1 % of ε) in every scene.
  CHECK(pattern_left < 0.5 * eps);
}

TEST_CASE("The null-space filter leaves a vibrating block's grid-resolved strain in place", "[mpm][filter][energy]") {
  // A uniform stretch of 1e-3 along x released: the block rings in its first mode, a strain
  // the grid represents, so the filter must not take its energy.
  auto stretched = [](const Vec3&) {
    Mat3 F = Mat3::Identity();
    F(0, 0) = 1.001;
    return F;
  };
  const Real c = std::sqrt(elastic(E, nu, rho).p_wave_modulus() / rho);
  Simulation sim = block(ShapeFunctionKind::ugimp, NullSpaceFilter::deformation);
  const Real initial = set_deformation(sim, stretched);
  sim.run_until(4 * side / c);
  const StepDiagnostics& d = sim.last_diagnostics();
  // Measured: the filter removed 0.007 % of the energy.
  CHECK(std::abs(d.transfer_dissipation) < 0.01 * initial);
  CHECK(d.strain_energy + d.kinetic_energy > 0.98 * initial);
}

TEST_CASE("The null-space filter refuses materials with a stress history", "[mpm][filter]") {
  PointSet points = empty_point_set(h, 2);
  add_points(points, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(side, side, side), "block");
  Settings s;
  s.cell_size = h;
  s.null_space_filter = NullSpaceFilter::deformation;
  CHECK_THROWS_AS(Simulation(points, {deformable("block", elastic(E, nu, rho))}, s), InputError);
  s.null_space_filter_every = 0;
  CHECK_THROWS_AS(Simulation(points, {deformable("block", titanium())}, s), InputError);
}
