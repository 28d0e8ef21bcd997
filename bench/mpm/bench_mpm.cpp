// Solver throughput: particle-updates per second (particles × steps / wall seconds) of the
// explicit MPM step on an elastic block, per shape function and thread count.
//   bench_mpm [--cells N] [--steps S] [--threads T] [--shape NAME] [--scheme NAME] [--ddmp-on-grid 0|1]
//             [--digest 1] [--dump FILE] [--contact-fields F]
// Prints one line per run; bench/mpm/run.sh runs the set recorded in docs/benchmarks.md.
// --digest 1 adds a hash of the final particle state (positions, velocities, F, σ, in the
// particles' original order): two builds that print the same digest computed bit-identical
// results, the check a kernel change that claims to keep the rounding must pass. --dump FILE
// writes the same state as raw doubles (21 per particle, id order) to compare two builds.
// --contact-fields F (F ≥ 1) runs with multi-field grid contact (mpm/field_contact.hpp):
// the block cut into F slabs along x, each a field (slabs 1.. tagged as groups, slab 0 the
// body's rest), every interface between slabs 1.. a frictionless contact plane: the cost of
// the contact step against one field (docs/contact.md, "Cost").
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "mpm/simulation.hpp"
#include "points/point_set.hpp"

using namespace latmpm;
using namespace latmpm::mpm;

namespace {
double cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

PointSet elastic_block(int cells, double h, int ppc) {
  PointSet ps;
  ps.cell_size = h;
  ps.ppc = ppc;
  ps.body_names = {"block"};
  const int n = cells * ppc;
  const double s = h / ppc;
  const size_t count = size_t(n) * n * n;
  ps.position.reserve(count);
  ps.volume.reserve(count);
  ps.body.reserve(count);
  ps.half_size.reserve(count);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        ps.position.emplace_back((i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s);
        ps.volume.push_back(s * s * s);
        ps.body.push_back(0);
        ps.half_size.emplace_back(s / 2, s / 2, s / 2);
      }
  return ps;
}

// Each particle's state in id order: position, velocity, F, σ (21 values).
std::vector<double> state_values(const Particles& ps) {
  std::vector<uint32_t> by_id(ps.size());
  for (size_t p = 0; p < ps.size(); ++p) by_id[ps.id[p]] = uint32_t(p);
  std::vector<double> out;
  out.reserve(ps.size() * 21);
  for (const uint32_t p : by_id) {
    for (int a = 0; a < 3; ++a) out.push_back(ps.position[p][a]);
    for (int a = 0; a < 3; ++a) out.push_back(ps.velocity[p][a]);
    for (int a = 0; a < 9; ++a) out.push_back(ps.deformation[p].data()[a]);
    for (int a = 0; a < 6; ++a) out.push_back(ps.stress[p][a]);
  }
  return out;
}

// FNV-1a over the bytes of each particle's state, particles taken in id order (the solver
// sorts them by bucket, and the order may differ between builds without the values differing).
uint64_t state_digest(const Particles& ps) {
  std::vector<uint32_t> by_id(ps.size());
  for (size_t p = 0; p < ps.size(); ++p) by_id[ps.id[p]] = uint32_t(p);
  uint64_t hash = 1469598103934665603ull;
  auto add = [&](const void* data, size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < bytes; ++i) hash = (hash ^ b[i]) * 1099511628211ull;
  };
  for (const uint32_t p : by_id) {
    add(ps.position[p].data(), sizeof(Real) * 3);
    add(ps.velocity[p].data(), sizeof(ParticleReal) * 3);
    add(ps.deformation[p].data(), sizeof(ParticleReal) * 9);
    add(ps.stress[p].data(), sizeof(ParticleReal) * 6);
  }
  return hash;
}
}  // namespace

int main(int argc, char** argv) {
  int cells = 40, steps = 20, threads = 0;
  std::vector<std::string> shapes = {"linear", "ugimp", "cpgimp", "bspline2", "bspline3", "ddmp"};
  std::string scheme = "usl";
  bool ddmp_on_grid = true;  // Settings::ddmp_on_grid; 0: DDMP's per-particle modified gradient
  bool digest = false;
  std::string dump;
  int contact_fields = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--cells") cells = std::atoi(value.c_str());
    else if (key == "--steps") steps = std::atoi(value.c_str());
    else if (key == "--threads") threads = std::atoi(value.c_str());
    else if (key == "--shape") shapes = {value};
    else if (key == "--scheme") scheme = value;
    else if (key == "--ddmp-on-grid") ddmp_on_grid = value != "0";
    else if (key == "--digest") digest = value != "0";
    else if (key == "--dump") dump = value;
    else if (key == "--contact-fields") contact_fields = std::atoi(value.c_str());
    else {
      std::fprintf(stderr, "bench_mpm: unknown option %s\n", key.c_str());
      return 1;
    }
  }
  const double h = 1e-3;
  PointSet points = elastic_block(cells, h, 2);
  std::vector<std::string> groups;
  for (int k = 1; k < contact_fields; ++k) {  // slab k: x in [k, k + 1) · cells h / F
    groups.push_back("slab" + std::to_string(k));
    auto& mask = points.tags[groups.back()];
    mask.resize(points.size());
    for (size_t p = 0; p < points.size(); ++p) mask[p] = int(points.position[p][0] / (cells * h) * contact_fields) == k;
  }
  for (const auto& shape : shapes) {
    Settings s;
    s.cell_size = h;
    s.shape_function = parse_shape_function(shape);
    s.scheme = parse_update_scheme(scheme);
    s.threads = threads;
    s.ddmp_on_grid = ddmp_on_grid;
    if (!ddmp_on_grid) s.ddmp_stabilization = 0;  // the per-particle form is unstabilized
    s.field_contact.enabled = contact_fields > 0;
    s.field_contact.groups = groups;
    BodySettings body;
    body.name = "block";
    body.material.young_modulus = 10e6;
    body.material.poisson_ratio = 0.4;
    body.material.density = 1050;
    Simulation sim(points, {body}, s);
    // A gentle initial shear-and-swirl velocity so the particles move and stress builds.
    for (size_t p = 0; p < sim.particles().size(); ++p) {
      const Vec3 x = sim.particles().position[p] / (cells * h) - Vec3::Constant(0.5);
      sim.mutable_particles().velocity[p] = ParticleVec3(x[1], -x[0], 0.2 * x[2]);
    }
    sim.step();  // warm-up: sorting, grid allocation
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = cpu_seconds();
    for (int n = 0; n < steps; ++n) sim.step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = cpu_seconds() - cpu_start;
    const double rate = double(sim.particles().size()) * steps / seconds;
    std::printf("shape %-8s scheme %s precision %s threads %d particles %zu steps %d: %.3f s (cpu %.3f s), "
                "%.3g particle-updates/s, %.0f B/particle + grid %.1f MB (%zu blocks)\n",
                shape.c_str(), scheme.c_str(), precision_name, threads, sim.particles().size(), steps, seconds, cpu, rate,
                double(sim.particle_memory_bytes()) / sim.particles().size(), sim.grid_memory_bytes() / 1e6,
                sim.active_grid_blocks());
    if (!dump.empty()) {
      const std::vector<double> values = state_values(sim.particles());
      FILE* f = std::fopen(dump.c_str(), "wb");
      if (!f || std::fwrite(values.data(), sizeof(double), values.size(), f) != values.size()) {
        std::fprintf(stderr, "bench_mpm: cannot write %s\n", dump.c_str());
        return 2;
      }
      std::fclose(f);
    }
    if (digest) std::printf("  state digest %016llx\n", (unsigned long long)state_digest(sim.particles()));
  }
  return 0;
}
