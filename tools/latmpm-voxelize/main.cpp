// latmpm-voxelize: geometry (a strut graph from latmpm-lattice, or an STL part) → material
// points on the solver's grid. Method and accuracy: docs/voxelize.md; file: docs/formats.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "core/units.hpp"
#include "core/command_line.hpp"
#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/hdf5_file.hpp"
#include "core/progress.hpp"
#include "core/provenance.hpp"
#include "core/tool_main.hpp"
#include "geometry/strut_graph.hpp"
#include "mesh/stl_file.hpp"
#include "points/xdmf.hpp"
#include "voxelize/mesh_placement.hpp"
#include "voxelize/resolution_guard.hpp"
#include "voxelize/resource_estimate.hpp"
#include "voxelize/solid_mesh_gate.hpp"
#include "voxelize/voxelize.hpp"

namespace {

const char* manual = R"(latmpm-voxelize: turn a lattice (or an STL part) into material points for latmpm-solve.

Input: a strut graph written by latmpm-lattice (a file, or - for stdin), or an STL file
(ASCII or binary) with --units for its length unit; --scale, --rotate, --place and
--translate place an STL part (scale, then rotations in order, then --place centres it on
x = y = 0 and stands it on z = 0, then translation, then --stand-on shifts it in z onto
the top of another point set; z is the compression axis). An OpenVDB level set is built straight from the strut graph's capsule distances, or
from the mesh (meshToLevelSet), and ppc^3 points per grid cell of size --cell are placed
on the solver's lattice (grid nodes at i*h, points at (i + (k + 1/2)/ppc)*h) inside the
solid. Points at the surface carry the fraction of their sub-cell inside the solid, so the
points' total volume matches the solid's (docs/voxelize.md). Bodies: the struts
("lattice" or "column"), each plate ("bottom_plate", "top_plate"; plates win where they
overlap struts), or "part" (--body) for an STL. Tags: "record" (bottom layer of the bottom
plate), "bottom_layer", "top_layer", and one per plate.
STL parts are checked with CGAL first (open boundaries, non-manifold edges, orientation,
degenerate and duplicate faces, self-intersections); --repair fixes what it can. A mesh
that is still not a closed solid is refused (exit status 2).
Output: an HDF5 point set (-o, - for stdout; layout in docs/formats.md) and, for a file,
an XDMF file beside it (out.h5 -> out.xmf) that ParaView opens directly.

Sample runs:
  $ latmpm-lattice --preset T2P30 -o - | latmpm-voxelize - --cell 0.64mm --ppc 2 -o t2p30-points.h5
  $ latmpm-voxelize $LATMPM_SOURCE_DIR/data/stl/cylinder.stl --units mm --cell 0.5mm --ppc 2 -o part.h5
  $ latmpm-voxelize $LATMPM_SOURCE_DIR/data/stl/sphere-ascii.stl --units mm --rotate x:90deg --translate 0mm,0mm,6mm --cell 1mm -o sphere.h5
  $ latmpm-voxelize $LATMPM_SOURCE_DIR/data/stl/cylinder.stl --units mm --rotate y:90deg --place --cell 0.5mm -o lying.h5
  $ latmpm-voxelize $LATMPM_SOURCE_DIR/data/stl/box-with-hole.stl --units mm --repair --cell 1mm -o repaired.h5
  $ latmpm-lattice --column --diameter 2.4mm --length 16mm -o - | latmpm-voxelize - --cell 0.2mm --ppc 2 -o - > column-points.h5 && h5ls -r column-points.h5
)";

void declare_options(latmpm::CommandLine& cl) {
  cl.positional("input", "strut graph (.h5 from latmpm-lattice) or STL file; - reads stdin");
  cl.option("cell", "LENGTH", "grid cell size h of the solver, e.g. 0.64mm");
  cl.option("ppc", "N", "points per cell per direction (ppc^3 per cell)", "2");
  cl.option("output", "PATH", "point-set HDF5 file, - for stdout");
  cl.alias('o', "output");
  cl.option("voxel", "LENGTH", "level-set voxel [default: half the point spacing, h/(2 ppc)]");
  cl.option("units", "UNIT", "STL: length unit of the file's coordinates, e.g. mm, m, in");
  cl.option("scale", "FACTOR", "STL: uniform scale factor", "1");
  cl.repeated_option("rotate", "AXIS:ANGLE", "STL: rotate about x, y or z, e.g. x:90deg (repeatable, in order)");
  cl.flag("place", "STL: after rotating, centre the part on x = y = 0 and stand it on z = 0");
  cl.option("translate", "X,Y,Z", "STL: translation after scaling, rotating and --place, e.g. 0mm,0mm,5mm");
  cl.option("stand-on", "POINTS", "STL: last, shift along z to stand on the top of this point set's points "
                                  "(e.g. a platen on the specimen)");
  cl.option("body", "NAME", "STL: body name of the part", "part");
  cl.flag("repair", "STL: fix what CGAL can (stitch, orient, drop degenerate faces, fill small holes)");
  cl.flag("no-self-intersection-check", "STL: skip the (slowest) check for self-intersections");
  cl.option("strut-groups", "N", "strut graphs: tag the struts' points by strut group in at most N colours "
                                 "(tags strut_c0...), for grid contact between struts (docs/contact.md)", "0");
  cl.flag("force", "voxelize even with less than one point across the thinnest strut");
  cl.option("max-memory", "BYTES", "refuse work estimated to need more memory, e.g. 8GB "
                                   "[default: the machine's physical memory]");
  cl.flag("quiet", "no summary or progress on stderr");
}

void refuse(const latmpm::CommandLine& cl, const std::vector<const char*>& options, const std::string& why) {
  for (const char* option : options)
    if (cl.given(option)) throw latmpm::InputError(std::string("--") + option, "", why);
}

std::string mm(double metres) { return latmpm::format_millimetres(metres, 4); }

// HDF5 files start with an 8-byte signature; anything else is taken for an STL.
bool is_hdf5(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[8] = {};
  in.read(head, 8);
  return in.gcount() == 8 && std::string(head, 8) == std::string("\x89HDF\r\n\x1a\n", 8);
}

// The highest point of a point set's sub-cells (m): where a part standing on it begins.
double points_top(const std::string& path) {
  using namespace latmpm;
  const PointSet points = read_point_set(Hdf5File(path, Hdf5File::Mode::read));
  if (points.size() == 0) throw InputError("--stand-on", path, "holds no points");
  double top = -INFINITY;
  for (size_t i = 0; i < points.size(); ++i) top = std::max(top, points.position[i].z() + points.half_size[i].z());
  return top;
}

double stl_metres_per_unit(const latmpm::CommandLine& cl) {
  using namespace latmpm;
  if (!cl.given("units")) throw InputError("--units", "", "required for STL input (the file's length unit, e.g. mm)");
  return parse_quantity("1" + cl.text("units"), dimension::length, "--units");
}

latmpm::TriangleMesh load_part(const latmpm::CommandLine& cl, const latmpm::InputFile& input, bool report) {
  using namespace latmpm;
  TriangleMesh mesh = read_stl(input.path(), stl_metres_per_unit(cl));
  Placement placement;
  placement.scale = cl.number("scale");
  if (!(placement.scale > 0)) throw InputError("--scale", "", "must be a positive factor");
  for (const std::string& r : cl.all("rotate")) placement.rotations.push_back(parse_axis_rotation(r, "--rotate"));
  placement.place = cl.flag_set("place");
  if (cl.given("stand-on")) placement.stand_on_z = points_top(cl.text("stand-on"));
  if (cl.given("translate")) placement.translation = parse_length_vector(cl.text("translate"), "--translate");
  place_mesh(mesh, placement);

  const MeshGateResult gate = pass_mesh_gate(mesh, input.display_name(), cl.flag_set("repair"),
                                             !cl.flag_set("no-self-intersection-check"));
  if (report) {
    if (gate.weld.vertices_welded) std::cerr << "  weld: " << describe(gate.weld) << "\n";
    std::cerr << "  mesh: " << describe(gate.found) << "\n";
    if (gate.repaired) {
      std::cerr << "  repair:";
      for (const auto& action : gate.repair.actions) std::cerr << " " << action << ";";
      std::cerr << "\n  repaired mesh: " << describe(gate.result) << "\n";
    }
  }
  return mesh;
}

void print_summary(const latmpm::Voxelized& v, double seconds) {
  const latmpm::PointSet& p = v.points;
  std::vector<size_t> count(p.body_names.size(), 0);
  for (int32_t b : p.body) ++count[static_cast<size_t>(b)];
  double total = 0;
  for (double x : p.volume) total += x;
  std::ostringstream os;
  os << "  points: " << p.size();
  for (size_t b = 0; b < count.size(); ++b) os << (b ? ", " : " (") << p.body_names[b] << " " << count[b];
  os << (count.empty() ? "" : ")") << "\n";
  char line[256];
  std::snprintf(line, sizeof line,
                "  volume: points %.6g mm^3, solid %.6g mm^3 (%+.3f %%)\n", total * 1e9,
                v.solid_volume * 1e9, 100 * (total / v.solid_volume - 1));
  os << line;
  if (v.dropped_volume > 0) {
    std::snprintf(line, sizeof line,
                  "  dropped: %.4g mm^3 in features thinner than a point spacing (no inside point)\n",
                  v.dropped_volume * 1e9);
    os << line;
  }
  for (const auto& [name, mask] : p.tags) {
    size_t n = 0;
    for (uint8_t m : mask) n += m;
    os << "  tag " << name << ": " << n << " points\n";
  }
  std::snprintf(line, sizeof line,
                "  time: level set %.2f s (%zu active voxels of %s), points %.2f s, total %.2f s\n",
                v.level_set_seconds, v.active_voxels, mm(v.voxel_size).c_str(), v.sampling_seconds, seconds);
  os << line;
  std::cerr << os.str();
}

int run(int argc, char** argv) {
  using namespace latmpm;
  const auto start = std::chrono::steady_clock::now();
  // 1. Options, checked before any work; the output is claimed up front.
  CommandLine cl("latmpm-voxelize", manual);
  declare_options(cl);
  cl.parse(argc, argv);
  const bool report = !cl.flag_set("quiet");
  if (!cl.given("cell")) throw InputError("--cell", "", "required: the solver's grid cell size, e.g. 0.64mm");
  if (!cl.given("output")) throw InputError("--output", "", "required: -o FILE (or - for stdout)");
  VoxelizeOptions options;
  options.cell_size = cl.quantity("cell", dimension::length);
  if (!(options.cell_size > 0)) throw InputError("--cell", "", "must be positive");
  const long ppc = cl.integer("ppc");
  if (ppc < 1 || ppc > 64) throw InputError("--ppc", "", "must be between 1 and 64");
  options.ppc = static_cast<int>(ppc);
  if (cl.given("voxel")) {
    options.voxel_size = cl.quantity("voxel", dimension::length);
    if (!(options.voxel_size > 0)) throw InputError("--voxel", "", "must be positive");
    if (options.voxel_size > options.spacing())
      throw InputError("--voxel", "", "coarser than the point spacing " + mm(options.spacing()) +
                                          " would misplace surface volumes; use at most that");
  }
  const long strut_groups = cl.integer("strut-groups");
  if (strut_groups < 0 || strut_groups > 30)
    throw InputError("--strut-groups", "", "must be between 0 (no groups) and 30 (grid contact's 32 fields less the body's and a plate's)");
  options.strut_groups = static_cast<int>(strut_groups);
  const double max_memory =
      cl.given("max-memory") ? parse_bytes(cl.text("max-memory"), "--max-memory") : physical_memory_bytes();
  InputFile input(cl.text("input"), "input");
  if (cl.text("output") != "-")
    refuse_aliased_outputs({{"--output", cl.text("output")}, {"its XDMF view", xdmf_path_beside(cl.text("output"))}});
  OutputFile output(cl.text("output"), "--output");
  std::unique_ptr<OutputFile> xdmf;
  if (!output.to_stdout()) xdmf = std::make_unique<OutputFile>(xdmf_path_beside(output.target()), "--output");
  if (report) std::cerr << "latmpm-voxelize: " << cl.resolved() << "\n";

  std::unique_ptr<Progress> progress;
  std::string stage;
  options.progress = [&](const std::string& name, double fraction) {
    if (name != stage) {
      if (progress) progress->finish();
      stage = name;
      progress = std::make_unique<Progress>("  " + name, 1.0, report);
    }
    progress->update(fraction);
  };

  // 2. Geometry → points.
  Provenance provenance = Provenance::for_run("latmpm-voxelize", argc, argv);
  provenance.inputs = {cl.text("input")};
  Voxelized result;
  std::string extent, hint;
  if (is_hdf5(input.path())) {
    refuse(cl, {"units", "rotate", "place", "translate", "stand-on", "body", "repair", "no-self-intersection-check"},
           "applies only to STL input");
    if (cl.text("scale") != "1") throw InputError("--scale", "", "applies only to STL input");
    const Hdf5File file(input.path(), Hdf5File::Mode::read);
    if (!holds_strut_graph(file))
      throw InputError(input.display_name(), "", "holds no strut graph (expected the output of latmpm-lattice)");
    const StrutGraph graph = read_strut_graph(file);
    provenance.inherit_from(file);
    // Resolution guard: points across the thinnest strut.
    const StrutResolution resolution = strut_resolution(graph, options.cell_size, options.ppc);
    if (report && resolution.has_struts) std::cerr << "  " << describe(resolution) << "\n";
    if (resolution.verdict == StrutResolution::Verdict::too_coarse && !cl.flag_set("force"))
      throw InputError("--cell", "", describe(resolution) + ": less than one point across; use a smaller --cell, "
                                     "a larger --ppc, or --force");
    if (resolution.verdict == StrutResolution::Verdict::coarse)
      std::cerr << "latmpm-voxelize: warning: fewer than 3 points across the thinnest strut: bending will be too stiff\n";
    if (resolution.has_struts && resolution.cells_across < 2)
      std::cerr << "latmpm-voxelize: warning: thin struts: " << describe(resolution) << ", "
                << mm(2 * options.cell_size - resolution.diameter) << " below two cells: volume and stiffness errors grow\n";
    const ResourceEstimate estimate = estimate_resources(graph, options);
    check_resources(estimate, options, max_memory, input.display_name());
    if (report) std::cerr << "  extent " << describe_extent(estimate.bounds) << "\n";
    result = voxelize_strut_graph(graph, options);
  } else {
    if (options.strut_groups > 0) throw InputError("--strut-groups", "", "applies only to a strut graph (an STL has no struts)");
    const TriangleMesh mesh = load_part(cl, input, report);
    const ResourceEstimate estimate = estimate_resources(mesh, options);
    hint = unit_hint(estimate.bounds, stl_metres_per_unit(cl), options.spacing());
    check_resources(estimate, options, max_memory, input.display_name(), hint);
    if (report) std::cerr << "  extent " << describe_extent(estimate.bounds) << "\n";
    result = voxelize_mesh(mesh, cl.text("body"), options);
    extent = describe_extent(estimate.bounds);
  }
  if (progress) progress->finish();
  if (result.thin.any())
    std::cerr << "latmpm-voxelize: warning: thin features: " << describe(result.thin, options.cell_size)
              << ": volume and stiffness errors grow\n";
  if (result.points.size() == 0)
    throw InputError(input.display_name(), "volume",
                     "the solid has zero volume at this resolution: no point inside (extent " + extent + ")" +
                         (hint.empty() ? "" : "; " + hint));
  result.points.validate("latmpm-voxelize");

  // 3. Output: point set with provenance, then the XDMF view beside it.
  {
    Hdf5File file(output.temp_path(), Hdf5File::Mode::create);
    write_provenance(file, provenance);
    write_point_set(file, result.points);
    file.close();
  }
  if (xdmf) {
    std::vector<std::string> tag_names;
    for (const auto& entry : result.points.tags) tag_names.push_back(entry.first);
    const std::string target = output.target();
    const std::string h5_name = target.substr(target.find_last_of('/') + 1);
    xdmf->write_text(xdmf_polyvertex(h5_name, result.points.size(), "/points/position",
                                     point_set_xdmf_attributes(tag_names)));
  }
  output.commit();
  if (xdmf) xdmf->commit();
  if (report)
    print_summary(result, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return latmpm::run_tool("latmpm-voxelize", argc, argv, run); }
