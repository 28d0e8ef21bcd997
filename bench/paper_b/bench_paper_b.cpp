// bench_paper_b curves OUT.csv: uniaxial-stress and simple-shear responses of the J2 model
// (paper B Eq. 9-13) for the 42CrMo4 and Ti-6Al-4V sets, one material point.
// bench_paper_b timing: nanoseconds per J2 update (plastic) and per CPDI1 stencil.
// bench_paper_b meshes PREFIX: the O-grid cylinders B1-B6 (d = l = 4 mm): a table of element
// counts and volumes on stdout, and PREFIX-B<k>.dat with every element edge (gnuplot).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "hexmesh/hex_mesh.hpp"
#include "mpm/cpdi.hpp"
#include "mpm/j2_plasticity.hpp"

using namespace latmpm;
using namespace latmpm::mpm;

namespace {

// One uniaxial-stress step: axial stretch increment `da`, the lateral stretch increment
// found by secant iteration so that σ_yy = σ_zz = 0.
J2Update uniaxial_step(const J2Parameters& p, const J2State& s, Real da, Real& lateral) {
  auto lateral_stress = [&](Real l) { return j2_update(p, Vec3(da, l, l).asDiagonal().toDenseMatrix(), s).cauchy[1]; };
  Real l0 = lateral, l1 = lateral * (1 + 1e-6);
  Real f0 = lateral_stress(l0), f1 = lateral_stress(l1);
  for (int it = 0; it < 50 && std::abs(f1) > 1e-6 * p.initial_yield && f1 != f0; ++it) {
    const Real l2 = l1 - f1 * (l1 - l0) / (f1 - f0);
    l0 = l1, f0 = f1, l1 = l2, f1 = lateral_stress(l1);
  }
  lateral = l1;
  return j2_update(p, Vec3(da, l1, l1).asDiagonal().toDenseMatrix(), s);
}

int curves(const char* path) {
  std::ofstream out(path);
  out << "material,loading,strain,stress_MPa,von_mises_MPa,alpha\n";
  const std::pair<const char*, J2Parameters> sets[] = {{"42CrMo4 400C", steel_42crmo4_400c()}, {"Ti-6Al-4V", ti6al4v()}};
  for (const auto& [name, p] : sets) {
    J2State s;
    Real lateral = 1, strain = 0;
    const int steps = 2000;
    const Real da = std::exp(0.5 / steps);
    for (int k = 1; k <= steps; ++k) {  // true (log) axial strain to 0.5
      const J2Update u = uniaxial_step(p, s, da, lateral);
      s = u.state;
      strain += std::log(da);
      if (k % 10 == 0)
        out << name << ",uniaxial," << strain << "," << u.cauchy[0] * 1e-6 << "," << von_mises(u.cauchy) * 1e-6 << ","
            << s.plastic_arc_length << "\n";
    }
    s = J2State();
    Mat3 f = Mat3::Identity();
    f(0, 1) = 1.0 / steps;  // simple shear to γ = 1
    for (int k = 1; k <= steps; ++k) {
      const J2Update u = j2_update(p, f, s);
      s = u.state;
      if (k % 10 == 0)
        out << name << ",shear," << Real(k) / steps << "," << u.cauchy[5] * 1e-6 << "," << von_mises(u.cauchy) * 1e-6
            << "," << s.plastic_arc_length << "\n";
    }
  }
  return 0;
}

int timing() {
  const J2Parameters p = steel_42crmo4_400c();
  J2State s;
  Mat3 f = Mat3::Identity();
  f(0, 1) = 2e-4;
  const int n = 1000000;
  Real sink = 0;
  for (int k = 0; k < 1000; ++k) s = j2_update(p, f, s).state;  // yielded
  auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < n; ++k) {
    const J2Update u = j2_update(p, f, s);
    s = u.state;
    sink += u.kirchhoff[5];
  }
  const double j2_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / n;
  const J2State at_rest;
  Mat3 small = Mat3::Identity();
  t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < n; ++k) {
    small(0, 1) = 1e-9 * (k % 100);
    sink += j2_update(p, small, at_rest).kirchhoff[5];
  }
  const double elastic_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / n;
  // A B5-like domain (about 0.2 mm) on G4 (0.4 mm).
  HexVertices x;
  for (int a = 0; a < 8; ++a) x[a] = Vec3(1.01e-3, 2.03e-3, 0.97e-3) + 0.1e-3 * hex_reference_vertex(a);
  t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < n; ++k) {
    x[k % 8][0] += 1e-12;
    sink += cpdi_stencil(x, 0.4e-3).weight[0];
  }
  const double cpdi_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / n;
  const CpdiDomain domain = make_cpdi_domain(x);
  Mat3 F = Mat3::Identity();
  t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < n; ++k) {
    F(0, 1) = 1e-9 * (k % 100);
    sink += cpdi_stencil(domain, Vec3(1.01e-3, 2.03e-3, 0.97e-3), F, 0.4e-3).weight[0];
  }
  const double convected_ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / n;
  std::printf("j2_update (plastic, 42CrMo4): %.0f ns\nj2_update (elastic): %.0f ns\ncpdi_stencil from vertices (B5-like domain on G4): %.0f ns\n"
              "cpdi_stencil convected from reference integrals: %.0f ns\n(checksum %g)\n",
              j2_ns, elastic_ns, cpdi_ns, convected_ns, sink);
  return 0;
}

int meshes(const std::string& prefix) {
  const double d = 4e-3, l = 4e-3, exact = M_PI * d * d / 4 * l;
  std::printf("| mesh | divisions (core, ring, axial) | elements | volume (mm^3) | against pi r^2 l |\n|---|---|---|---|---|\n");
  for (int level = 1; level <= 6; ++level) {
    const CylinderMeshSpec spec = paper_b_cylinder(level, d, l);
    const HexMesh mesh = cylinder_hex_mesh(spec);
    const double volume = hex_mesh_volume(mesh);
    std::printf("| B%d | %d, %d, %d | %zu | %.4f | %+.3f %% |\n", level, spec.core_divisions, spec.ring_divisions,
                spec.axial_divisions, mesh.elements.size(), volume * 1e9, 100 * (volume / exact - 1));
    std::ofstream out(prefix + "-B" + std::to_string(level) + ".dat");
    static const int edge[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& e : mesh.elements)
      for (const auto& ab : edge) {
        const Eigen::Vector3d a = 1e3 * mesh.nodes[e[size_t(ab[0])]], b = 1e3 * mesh.nodes[e[size_t(ab[1])]];
        out << a.x() << " " << a.y() << " " << a.z() << "\n" << b.x() << " " << b.y() << " " << b.z() << "\n\n\n";
      }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && !std::strcmp(argv[1], "curves")) return curves(argv[2]);
  if (argc == 2 && !std::strcmp(argv[1], "timing")) return timing();
  if (argc == 3 && !std::strcmp(argv[1], "meshes")) return meshes(argv[2]);
  std::fprintf(stderr, "usage: bench_paper_b curves OUT.csv | timing | meshes PREFIX\n");
  return 1;
}
