// Benchmark: T2P30 strut graph, its level set, surface mesh and STL at a given voxel size.
// usage: bench_lattice [VOXEL_MM=0.1] [REPEATS=5] [STL_PATH=/tmp/latmpm-bench.stl]
// Prints the median of REPEATS for the graph and the phases of one STL run.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "geometry/lattice.hpp"
#include "levelset/level_set_mesh.hpp"
#include "levelset/strut_level_set.hpp"
#include "levelset/strut_surface.hpp"
#include "mesh/stl_file.hpp"

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  using namespace latmpm;
  const double voxel = (argc > 1 ? std::atof(argv[1]) : 0.1) * 1e-3;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
  const std::string stl_path = argc > 3 ? argv[3] : "/tmp/latmpm-bench.stl";

  std::vector<double> graph_s, level_set_s, mesh_s, stl_s;
  StrutGraph graph;
  for (int i = 0; i < std::max(repeats, 1) * 10; ++i) {
    const auto start = std::chrono::steady_clock::now();
    graph = build_lattice(preset_lattice("T2P30"));
    graph_s.push_back(seconds_since(start));
  }
  size_t triangles = 0;
  for (int i = 0; i < repeats; ++i) {
    auto start = std::chrono::steady_clock::now();
    const auto grid = strut_graph_level_set(graph, voxel, 2.0);  // the band --stl uses
    level_set_s.push_back(seconds_since(start));
    start = std::chrono::steady_clock::now();
    const TriangleMesh mesh = strut_graph_surface(graph, voxel);  // level set + mesh
    mesh_s.push_back(seconds_since(start));
    triangles = mesh.triangles.size();
    start = std::chrono::steady_clock::now();
    write_stl(mesh, stl_path, 1e-3);
    stl_s.push_back(seconds_since(start));
  }
  std::remove(stl_path.c_str());
  std::printf("T2P30 strut graph (%zu nodes, %zu struts): median %.4f s of %zu\n", graph.nodes.size(),
              graph.struts.size(), median(graph_s), graph_s.size());
  std::printf("at %.3f mm voxels: level set alone %.2f s; surface (level set + mesh, %zu triangles) %.2f s; "
              "binary STL write %.2f s; surface + STL %.2f s (medians of %d)\n",
              voxel * 1e3, median(level_set_s), triangles, median(mesh_s), median(stl_s),
              median(mesh_s) + median(stl_s), repeats);
  return 0;
}
