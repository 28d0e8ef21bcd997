// latmpm-lattice: the specimen geometry as a strut graph (paper A Sec. 3 lattices, the Sec. 4
// column, other cell types), optionally its surface as STL and exact CSG as STEP.
// Geometry rules and decisions: docs/geometry.md; file layout: docs/formats.md.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "cad/step_export.hpp"
#include "core/command_line.hpp"
#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/hdf5_file.hpp"
#include "core/progress.hpp"
#include "core/provenance.hpp"
#include "core/tool_main.hpp"
#include "geometry/column.hpp"
#include "geometry/graph_checks.hpp"
#include "geometry/lattice.hpp"
#include "geometry/plates.hpp"
#include "levelset/level_set_units.hpp"
#include "levelset/solid_measures.hpp"
#include "levelset/strut_level_set.hpp"
#include "levelset/strut_surface.hpp"
#include "mesh/stl_file.hpp"

namespace {

const char* manual = R"(latmpm-lattice: build a lattice specimen (or a buckling column) as a strut graph.

Struts are capsules (cylinders with round ends) joined at nodes; the top and bottom plates
are solid boxes; z is the compression axis, the bottom plate starts at z = 0 and the
footprint is centred on x = y = 0. The tetrahedral cell is paper A's (three struts of
length L at angle phi to the horizontal, a vertical strut of 2L/3, layers stacked ABC);
--preset T1P20 ... T2P40 gives the paper's six specimens (L = 8 mm, t = 1.6 or 2.4 mm,
phi = 20, 30, 40 deg, 5x5x5 cells, 3 mm plates). Other cells: bcc, octet. --column gives
the solid cylinder of the buckling test (flat ends, exactly --length long).
Output: the strut graph as HDF5 (-o, - for stdout), optionally a closed outward STL surface
in millimetres (OpenVDB level set meshed at --voxel; T2P30 at 0.1 mm: 10 M triangles, ~4 s)
and exact STEP CSG through gmsh/OpenCASCADE (slow: T2P30 takes about 2 minutes).
A summary goes to stderr: bounding box, counts, solid volume, relative density.
Rules and decisions: docs/geometry.md.

Sample runs:
  $ latmpm-lattice --preset T2P30 -o t2p30.h5
  $ latmpm-lattice --preset T1P40 --stl t1p40.stl --voxel 0.2mm -o t1p40.h5
  $ latmpm-lattice --column --diameter 2.4mm --length 16mm -o column.h5
  $ latmpm-lattice --cell bcc --cells 3x3x3 --strut-length 5mm --strut-diameter 1mm -o - > bcc.h5 && h5ls -r bcc.h5
  $ latmpm-lattice --preset T2P30 --cells 1x1x1 --plates 2mm --step cell.step -o cell.h5
)";

void declare_options(latmpm::CommandLine& cl) {
  cl.option("preset", "NAME", "paper A specimen: T1P20 T1P30 T1P40 T2P20 T2P30 T2P40 "
                              "(options below override its values)");
  cl.option("cell", "TYPE", "cell type: tetrahedral, bcc, octet [default: tetrahedral]");
  cl.option("strut-length", "LENGTH", "strut length L (tetrahedral: the inclined struts), e.g. 8mm");
  cl.option("strut-diameter", "LENGTH", "strut diameter t, e.g. 2.4mm");
  cl.option("angle", "ANGLE", "tetrahedral: angle phi of the inclined struts to the horizontal, e.g. 30deg");
  cl.option("cells", "NXxNYxNZ", "cells along x, y and z (tetrahedral: tripods per row, rows, layers) "
                                 "[default: 5x5x5]");
  cl.option("stacking", "ORDER", "tetrahedral: ABC, or ACB (mirrored tripods) [default: ABC]");
  cl.option("footprint", "SHAPE", "tetrahedral: brick (rows of NX) or rhombic (lattice parallelogram) "
                                  "[default: brick]");
  cl.option("plates", "THICKNESS", "top and bottom plates of this thickness, at least the strut radius (preset: 3mm)");
  cl.flag("no-plates", "no plates (overrides a preset's)");
  cl.option("plate-margin", "LENGTH", "plates overhang the lattice (or the column) by this on each side "
                                      "[default: 0mm]");
  cl.option("name", "NAME", "name recorded in the file [default: the preset or cell name]");
  cl.flag("column", "a solid buckling column instead of a lattice (--diameter, --length)");
  cl.option("diameter", "LENGTH", "column diameter, e.g. 2.4mm");
  cl.option("length", "LENGTH", "column length, e.g. 16mm");
  cl.option("end-plates", "THICKNESS", "column: end plates of this thickness (default none)");
  cl.option("output", "PATH", "strut-graph HDF5 file, - for stdout");
  cl.alias('o', "output");
  cl.option("stl", "PATH", "also write the solid's surface as binary STL in millimetres");
  cl.flag("stl-ascii", "write the STL as ASCII");
  cl.option("voxel", "LENGTH", "voxel size of the level set meshed for --stl [default: t/10]");
  cl.option("step", "PATH", "also write exact CSG as STEP (gmsh/OpenCASCADE; slow for large lattices)");
  cl.option("summary-voxel", "LENGTH", "voxel size of the level set for the summary's volume [default: t/16]");
  cl.flag("quiet", "no summary or progress on stderr");
}

// Options that only make sense in one mode are refused in the other (unused options stop the run).
void refuse(const latmpm::CommandLine& cl, const std::vector<const char*>& options, const std::string& why) {
  for (const char* option : options)
    if (cl.given(option)) throw latmpm::InputError(std::string("--") + option, "", why);
}

latmpm::StrutGraph column_from(const latmpm::CommandLine& cl) {
  using namespace latmpm;
  refuse(cl, {"preset", "cell", "strut-length", "strut-diameter", "angle", "cells", "stacking",
              "footprint", "plates", "no-plates"},
         "does not apply to --column (use --diameter, --length, --end-plates)");
  for (const char* option : {"diameter", "length"})
    if (!cl.given(option)) throw UsageError(std::string("--") + option + ": required with --column");
  ColumnSpec spec;
  spec.diameter = cl.quantity("diameter", dimension::length);
  spec.length = cl.quantity("length", dimension::length);
  if (cl.given("end-plates")) {
    spec.end_plate_thickness = cl.quantity("end-plates", dimension::length);
    if (!(spec.end_plate_thickness > 0)) throw InputError("--end-plates", "", "must be positive");
  }
  if (cl.given("plate-margin")) spec.plate_margin = cl.quantity("plate-margin", dimension::length);
  return build_column(spec);
}

latmpm::StrutGraph lattice_from(const latmpm::CommandLine& cl) {
  using namespace latmpm;
  refuse(cl, {"diameter", "length", "end-plates"}, "applies only to --column");
  LatticeSpec spec;
  if (cl.given("preset")) {
    spec = preset_lattice(cl.text("preset"));
    if (cl.given("cell") && cl.text("cell") != spec.cell)
      throw InputError("--cell", "", "the presets are tetrahedral lattices; drop --preset for '" + cl.text("cell") + "'");
  } else {
    if (cl.given("cell")) spec.cell = cl.text("cell");
    for (const char* option : {"strut-length", "strut-diameter"})
      if (!cl.given(option)) throw UsageError(std::string("--") + option + ": required (or use --preset)");
    if (cell_uses_angle(spec.cell) && !cl.given("angle"))
      throw UsageError("--angle: required for the " + spec.cell + " cell (or use --preset)");
  }
  if (!cell_uses_angle(spec.cell)) refuse(cl, {"stacking", "footprint"}, "applies only to --cell tetrahedral");
  if (cl.given("strut-length")) spec.strut_length = cl.quantity("strut-length", dimension::length);
  if (cl.given("strut-diameter")) spec.strut_diameter = cl.quantity("strut-diameter", dimension::length);
  if (cl.given("angle")) spec.angle = cl.quantity("angle", dimension::angle);
  if (cl.given("cells")) spec.cells = parse_cell_counts(cl.text("cells"));
  if (cl.given("stacking")) spec.stacking = parse_stacking(cl.text("stacking"));
  if (cl.given("footprint")) spec.footprint = parse_footprint(cl.text("footprint"));
  if (cl.given("plates") && cl.flag_set("no-plates"))
    throw InputError("--no-plates", "", "contradicts --plates");
  if (cl.given("plates")) {
    spec.plate_thickness = cl.quantity("plates", dimension::length);
    if (!(spec.plate_thickness > 0)) throw InputError("--plates", "", "the plate thickness must be positive (or --no-plates)");
  }
  if (cl.flag_set("no-plates")) spec.plate_thickness = 0;
  if (cl.given("plate-margin")) spec.plate_margin = cl.quantity("plate-margin", dimension::length);
  return build_lattice(spec);
}

double smallest_radius(const latmpm::StrutGraph& g) {
  double r = INFINITY;
  for (const auto& s : g.struts) r = std::min(r, s.radius);
  return r;
}

// A voxel size for the solid: positive, and not so fine that the level set cannot be held.
double voxel_size(const latmpm::CommandLine& cl, const char* option, const latmpm::StrutGraph& g) {
  const double value = cl.quantity(option, latmpm::dimension::length);
  if (!(value > 0)) throw latmpm::InputError(std::string("--") + option, "", "must be positive");
  if (value < latmpm::smallest_voxel_m)
    throw latmpm::InputError(std::string("--") + option, "", "finer than the smallest level-set voxel, 0.1 um");
  const double across = latmpm::solid_bounds(g).sizes().maxCoeff() / value;
  if (across > 20000)
    throw latmpm::InputError(std::string("--") + option, "",
                             "too fine for this solid (" + std::to_string(long(across)) + " voxels across; at most 20000)");
  return value;
}

std::string millimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", metres * 1e3);
  return text;
}

// Level set with progress (time left) on stderr.
openvdb::FloatGrid::Ptr level_set_with_progress(const latmpm::StrutGraph& g, double voxel,
                                                double half_width_voxels, bool report) {
  latmpm::Progress progress("level set at " + millimetres(voxel) + " mm", 1.0, report);
  auto grid = latmpm::strut_graph_level_set(g, voxel, half_width_voxels, [&](double f) { progress.update(f); });
  progress.finish();
  return grid;
}

void print_summary(const latmpm::StrutGraph& g, const latmpm::SolidMeasures& m, double radius) {
  using namespace latmpm;
  const Eigen::AlignedBox3d box = solid_bounds(g);
  std::ostringstream os;
  os << "latmpm-lattice: " << g.name << " (" << (g.parameters.count("cell") ? g.parameters.at("cell") : "?")
     << "): " << g.nodes.size() << " nodes, " << g.struts.size() << " struts, " << g.plates.size()
     << " plates, ";
  const size_t bodies = count_bodies(g, 1e-9 * box.sizes().maxCoeff());
  os << (bodies == 1 ? "one connected body\n" : std::to_string(bodies) + " separate bodies (not one print!)\n");
  os << "  bounding box  x [" << millimetres(box.min().x()) << ", " << millimetres(box.max().x()) << "]  y ["
     << millimetres(box.min().y()) << ", " << millimetres(box.max().y()) << "]  z [" << millimetres(box.min().z())
     << ", " << millimetres(box.max().z()) << "] mm  (" << millimetres(box.sizes().x()) << " x "
     << millimetres(box.sizes().y()) << " x " << millimetres(box.sizes().z()) << " mm)\n";
  char line[256];
  std::snprintf(line, sizeof line,
                "  solid volume  %.1f mm^3 (plates %.1f mm^3, lattice %.1f mm^3); level set at %s mm voxels, "
                "estimated error within +-%.1f %%\n",
                m.solid_volume * 1e9, m.plate_volume * 1e9, m.lattice_volume * 1e9,
                millimetres(m.voxel_size).c_str(), 100 * expected_volume_error(m.voxel_size, radius));
  os << line;
  if (g.strut_body == "column") {
    std::cerr << os.str();
    return;
  }
  std::snprintf(line, sizeof line, "  relative density  %.4f (lattice solid / %.1f mm^3 footprint x height%s)\n",
                m.relative_density, m.envelope_volume * 1e9, g.plates.empty() ? "" : " between the plates");
  os << line;
  std::cerr << os.str();
}

int run(int argc, char** argv) {
  using namespace latmpm;
  // 1. Options, checked before any work; every output is claimed up front so an unwritable
  //    path fails at once and nothing is left behind on any error.
  CommandLine cl("latmpm-lattice", manual);
  declare_options(cl);
  cl.parse(argc, argv);
  const bool report = !cl.flag_set("quiet");
  int to_stdout = 0;
  for (const char* option : {"output", "stl", "step"}) to_stdout += cl.given(option) && cl.text(option) == "-";
  if (to_stdout > 1) throw InputError("--output", "", "only one output can go to stdout ('-')");
  if (cl.flag_set("stl-ascii") && !cl.given("stl")) throw InputError("--stl-ascii", "", "needs --stl PATH");
  if (cl.given("voxel") && !cl.given("stl")) throw InputError("--voxel", "", "applies to --stl (see --summary-voxel)");

  // 2. The geometry.
  StrutGraph graph = cl.flag_set("column") ? column_from(cl) : lattice_from(cl);
  if (cl.given("name")) graph.name = cl.text("name");
  const double radius = smallest_radius(graph);
  const double stl_voxel = cl.given("voxel") ? voxel_size(cl, "voxel", graph) : 2 * radius / 10;
  const double summary_voxel =
      cl.given("summary-voxel") ? voxel_size(cl, "summary-voxel", graph) : 2 * radius / 16;
  refuse_aliased_outputs({{"--output", cl.text("output")}, {"--stl", cl.text("stl")}, {"--step", cl.text("step")}});
  std::unique_ptr<OutputFile> h5_out, stl_out, step_out;
  if (cl.given("output")) h5_out = std::make_unique<OutputFile>(cl.text("output"), "--output");
  if (cl.given("stl")) stl_out = std::make_unique<OutputFile>(cl.text("stl"), "--stl");
  if (cl.given("step")) step_out = std::make_unique<OutputFile>(cl.text("step"), "--step");
  if (report) std::cerr << "latmpm-lattice: " << cl.resolved() << "\n";

  // 3. Strut graph file with provenance.
  if (h5_out) {
    Hdf5File file(h5_out->temp_path(), Hdf5File::Mode::create);
    write_provenance(file, Provenance::for_run("latmpm-lattice", argc, argv));
    write_strut_graph(file, graph);
    file.close();
  }

  // 4. Surfaces.
  if (stl_out) {
    Progress progress("surface at " + millimetres(stl_voxel) + " mm voxels", 1.0, report);
    const TriangleMesh mesh = strut_graph_surface(graph, stl_voxel, [&](double f) { progress.update(f); });
    write_stl(mesh, stl_out->temp_path(), 1e-3, cl.flag_set("stl-ascii") ? StlEncoding::ascii : StlEncoding::binary);
    progress.finish(std::to_string(mesh.triangles.size()) + " triangles");
  }
  if (step_out) {
    const StepReport step = write_step(graph, step_out->temp_path(), report);
    if (report)
      std::cerr << "  STEP: " << step.solids << " solids fused in " << format_duration(step.seconds) << "\n";
  }

  // 5. The summary's measures (the volume needs the full ±3-voxel band, LevelSetMeasure's
  //    smeared delta), then, everything having succeeded, publish the files.
  SolidMeasures measures;
  if (report) measures = measure_solid(graph, *level_set_with_progress(graph, summary_voxel, 3.0, report));
  for (auto* out : {h5_out.get(), stl_out.get(), step_out.get()})
    if (out) out->commit();
  if (report) print_summary(graph, measures, radius);
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return latmpm::run_tool("latmpm-lattice", argc, argv, run); }
