// Solver throughput: particle-updates per second (particles × steps / wall seconds) of the
// explicit MPM step on an elastic block, per shape function and thread count.
//   bench_mpm [--cells N] [--steps S] [--threads T] [--shape NAME] [--scheme NAME] [--ddmp-on-grid 0|1]
// Prints one line per run; bench/mpm/run.sh runs the set recorded in docs/benchmarks.md.
#include <chrono>
#include <ctime>
#include <cstdio>
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
}  // namespace

int main(int argc, char** argv) {
  int cells = 40, steps = 20, threads = 0;
  std::vector<std::string> shapes = {"linear", "ugimp", "cpgimp", "bspline2", "bspline3", "ddmp"};
  std::string scheme = "usl";
  bool ddmp_on_grid = true;  // Settings::ddmp_on_grid; 0: DDMP's per-particle modified gradient
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--cells") cells = std::atoi(value.c_str());
    else if (key == "--steps") steps = std::atoi(value.c_str());
    else if (key == "--threads") threads = std::atoi(value.c_str());
    else if (key == "--shape") shapes = {value};
    else if (key == "--scheme") scheme = value;
    else if (key == "--ddmp-on-grid") ddmp_on_grid = value != "0";
    else {
      std::fprintf(stderr, "bench_mpm: unknown option %s\n", key.c_str());
      return 1;
    }
  }
  const double h = 1e-3;
  const PointSet points = elastic_block(cells, h, 2);
  for (const auto& shape : shapes) {
    Settings s;
    s.cell_size = h;
    s.shape_function = parse_shape_function(shape);
    s.scheme = parse_update_scheme(scheme);
    s.threads = threads;
    s.ddmp_on_grid = ddmp_on_grid;
    BodySettings body;
    body.name = "block";
    body.material.young_modulus = 10e6;
    body.material.poisson_ratio = 0.4;
    body.material.density = 1050;
    Simulation sim(points, {body}, s);
    // A gentle initial shear-and-swirl velocity so the particles move and stress builds.
    for (size_t p = 0; p < sim.particles().size(); ++p) {
      const Vec3 x = sim.particles().position[p] / (cells * h) - Vec3::Constant(0.5);
      sim.mutable_particles().velocity[p] = Vec3(x[1], -x[0], 0.2 * x[2]);
    }
    sim.step();  // warm-up: sorting, grid allocation
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = cpu_seconds();
    for (int n = 0; n < steps; ++n) sim.step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu = cpu_seconds() - cpu_start;
    const double rate = double(sim.particles().size()) * steps / seconds;
    std::printf("shape %-8s scheme %s threads %d particles %zu steps %d: %.3f s (cpu %.3f s), %.3g particle-updates/s, "
                "%.0f B/particle + grid %.1f MB (%zu blocks)\n",
                shape.c_str(), scheme.c_str(), threads, sim.particles().size(), steps, seconds, cpu, rate,
                double(sim.particle_memory_bytes()) / sim.particles().size(), sim.grid_memory_bytes() / 1e6,
                sim.active_grid_blocks());
  }
  return 0;
}
