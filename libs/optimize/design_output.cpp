#include "optimize/design_output.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/file_transfer.hpp"

namespace latmpm::optimize {
namespace {

// Comment lines; control characters (user text from the command line) shown as '?', so no
// line of it can become CSV data or gnuplot code.
std::string comments(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) {
    s += "# ";
    for (char c : l) s += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
    s += "\n";
  }
  return s;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

void write_method_files(const std::string& directory, const OptimizeScene& scene, const MethodOutcome& o,
                        const std::vector<std::string>& provenance_lines) {
  const std::string stem = directory + "/" + o.method;
  std::ostringstream h;
  h << comments(provenance_lines) << "iteration,compliance_J,volume_fraction,band_threshold,seconds,active_points,unknowns\n";
  for (const auto& r : o.result.history)
    h << r.iteration << "," << number(r.compliance) << "," << number(r.volume_fraction) << "," << number(r.threshold)
      << "," << number(r.seconds) << "," << r.active_points << "," << r.unknowns << "\n";
  write_file_atomically(stem + "-history.csv", h.str(), "--output");

  std::ostringstream d;
  d << comments(provenance_lines) << "x_mm,y_mm,z_mm,density,binary\n";
  const DesignGrid& g = scene.grid;
  for (size_t q = 0; q < g.point_count(); ++q) {
    const Vec3 x = 1e3 * g.position(q);
    d << number(x[0]) << "," << number(x[1]) << "," << number(x[2]) << "," << number(o.result.density[q]) << ","
      << int(o.binary[q]) << "\n";
  }
  write_file_atomically(stem + "-design.csv", d.str(), "--output");

  // The picture: 2D as an image of the binary design, 3D as its solid points.
  std::ostringstream gp;
  gp << comments(provenance_lines) << "set terminal pngcairo size 1200,600 noenhanced\n"
     << "set output '" << o.method << "-design.png'\n"
     << "set datafile separator ','\nset size ratio -1\nunset key\nunset colorbox\n"
     << "set palette defined (0 'white', 1 'black')\nset cbrange [0:1]\n"
     << "set title '" << o.method << ": volume " << number(100 * o.volume_fraction) << " %, compliance "
     << number(o.compliance_binary) << " J (refined " << number(o.compliance_refined) << " J)'\n"
     << "set xlabel 'x (mm)'\nset ylabel 'y (mm)'\n";
  if (g.planar)
    gp << "plot '" << o.method << "-design.csv' every ::1 using 1:2:5 with image\n";
  else
    gp << "set view 70,20\nset view equal xyz\nset zlabel 'z (mm)'\n"
       << "splot '" << o.method << "-design.csv' every ::1 using 1:2:($5 > 0.5 ? $3 : 1/0) with points pt 7 ps 0.5 lc rgb 'black'\n";
  write_file_atomically(stem + "-design.gp", gp.str(), "--output");
}

void write_summary(const std::string& directory, const OptimizeScene& scene, const std::vector<MethodOutcome>& outcomes,
                   const std::vector<ExportReport>& exports, const std::vector<std::string>& provenance_lines) {
  // The exported (mirrored) part's stiffness under the one load, from the compliance: C = F u / 2
  // (u the load's mean displacement along it) gives the model k = F / u = F² / (2 C), and each
  // mirror doubles the force at the same displacement.
  Vec3 force = Vec3::Zero();
  for (const Load& load : scene.load_case.loads) force += load.force;
  const double mirrors = std::pow(2.0, double(symmetry_planes(scene.grid, scene.load_case).size()));
  auto part_stiffness = [&](double compliance) { return mirrors * force.squaredNorm() / (2 * compliance); };
  // C = F u / 2 holds for linear elasticity only (neo-Hookean C is the strain energy plus the
  // stabilisation's), so the stiffness is written for linear designs only.
  const bool one_load = scene.load_case.loads.size() == 1 && scene.material.model == mpm::MaterialKind::linear_elastic;
  std::ostringstream s;
  s << comments(provenance_lines);
  const Index3 c = scene.grid.cells;
  s << "scene = '" << scene.source << "'\n"
    << "cells = [" << c[0] << ", " << c[1] << ", " << c[2] << "]\n"
    << "points_per_cell = " << scene.grid.per_cell << "\n"
    << "volume_bound = " << number(scene.settings.volume_fraction) << "\n"
    << "refine = " << scene.refine << "\n";
  for (size_t i = 0; i < outcomes.size(); ++i) {
    const MethodOutcome& o = outcomes[i];
    const bool own_bound = o.method == "leto" && scene.leto_volume_fraction > 0;
    s << "\n[" << o.method << "]\n"
      << "volume_bound = " << number(own_bound ? scene.leto_volume_fraction : scene.settings.volume_fraction) << "\n"
      << "iterations = " << o.result.history.size() << "\n"
      << "converged = " << (o.result.converged ? "true" : "false") << "\n"
      << "seconds_per_iteration = " << number(o.seconds_per_iteration) << "\n"
      << "volume_fraction = " << number(o.volume_fraction) << "  # binary design\n"
      << "compliance_last_J = " << number(o.compliance_last) << "\n"
      << "compliance_J = " << number(o.compliance_binary) << "  # binary design, optimisation grid\n"
      << "compliance_refined_J = " << number(o.compliance_refined) << "  # binary design, grid refined " << scene.refine
      << " times\n"
      << "connectivity_corrections = " << o.corrections << "\n"
      << "linear_fallbacks = " << o.result.linear_fallbacks << "  # neo-Hookean iterations stepped on the linear compliance\n"
      << "components = " << o.components << "\n";
    if (scene.evaluate_other_model)
      s << "compliance_other_model_J = " << number(o.compliance_other_model) << "  # binary design, optimisation grid, "
        << (scene.material.model == mpm::MaterialKind::linear_elastic ? "neo-Hookean" : "linear elastic") << "\n";
    if (i < exports.size())
      s << "part_points_volume_mm3 = " << number(1e9 * exports[i].solid_volume)
        << "  # the exported part (mirrored whole): its solid points\n";
    if (one_load && o.compliance_binary > 0)
      s << "part_stiffness_N_per_m = " << number(part_stiffness(o.compliance_binary))
        << "  # the exported part under the load: 2^mirrors F^2 / (2 C)\n";
    if (one_load && o.compliance_refined > 0)
      s << "part_stiffness_refined_N_per_m = " << number(part_stiffness(o.compliance_refined)) << "  # the same from C refined\n";
  }
  write_file_atomically(directory + "/summary.toml", s.str(), "--output");
}

}  // namespace latmpm::optimize
