// latmpm-hexmesh: hexahedral meshes → CPDI1 material points (paper B Sec. 2.2, Fig. 7).
// Meshing and reading through gmsh: libs/hexmesh; file: docs/formats.md; docs/paper-b.md.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "core/command_line.hpp"
#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/hdf5_file.hpp"
#include "core/interruption.hpp"
#include "core/provenance.hpp"
#include "core/tool_main.hpp"
#include "core/units.hpp"
#include "hexmesh/hex_mesh.hpp"
#include "hexmesh/hex_points.hpp"
#include "points/xdmf.hpp"

namespace {

const char* manual = R"(latmpm-hexmesh: hexahedral meshes as CPDI1 material points for latmpm-solve.

Either builds a structured O-grid cylinder about the z axis through gmsh (--cylinder: a
transfinite core square and four ring patches, recombined and extruded in layers, so every
element is an 8-node hexahedron), with paper B's refinement levels B1-B6 (--level k: core
2k, ring k, axial 4k divisions, 48 k^3 elements) or explicit --divisions; or reads a gmsh
.msh file of 8-node hexahedra (input, with --units for its length unit). Each element
becomes one material point at its centroid with its exact (trilinear) volume and its eight
vertices, the CPDI1 particle domain (paper B Eq. 7). Other volume elements (tetrahedra,
prisms, 20/27-node hexahedra) and inverted elements are refused (exit status 2).
Output: an HDF5 point set with /points/domain_vertices (docs/formats.md; -o, - for stdout),
an XDMF file beside a file output, and with --msh the generated mesh itself.

Sample runs:
  $ latmpm-hexmesh --cylinder --diameter 4mm --height 4mm --level 2 --cell 0.4mm -o b2.h5
  $ latmpm-hexmesh --cylinder --diameter 4mm --height 4mm --divisions 4,2,6 --cell 0.4mm --msh cyl.msh -o cyl.h5
  $ latmpm-hexmesh --cylinder --diameter 4mm --height 4mm --level 1 --cell 0.4mm --msh b1.msh -o - > /dev/null && latmpm-hexmesh b1.msh --units m --cell 0.4mm -o b1-read.h5
)";

void declare_options(latmpm::CommandLine& cl) {
  cl.positional("input", "gmsh .msh file of 8-node hexahedra (omit with --cylinder)", false);
  cl.flag("cylinder", "build an O-grid cylinder about z, from z = 0 to --height");
  cl.option("diameter", "LENGTH", "cylinder diameter, e.g. 4mm");
  cl.option("height", "LENGTH", "cylinder height, e.g. 4mm");
  cl.option("level", "K", "paper B refinement level Bk (1-12): divisions 2k,k,4k");
  cl.option("divisions", "CORE,RING,AXIAL", "cylinder divisions: core square side, ring, axial layers");
  cl.option("units", "UNIT", "input: length unit of the .msh coordinates, e.g. mm, m");
  cl.option("cell", "LENGTH", "grid cell size h of the solver the points are for, e.g. 0.4mm");
  cl.option("body", "NAME", "body name of the points", "specimen");
  cl.option("msh", "PATH", "--cylinder: also write the generated mesh (gmsh .msh)");
  cl.option("output", "PATH", "point-set HDF5 file, - for stdout");
  cl.alias('o', "output");
  cl.flag("quiet", "no summary on stderr");
}

latmpm::CylinderMeshSpec cylinder_spec(const latmpm::CommandLine& cl) {
  using namespace latmpm;
  for (const char* needed : {"diameter", "height"})
    if (!cl.given(needed)) throw UsageError(std::string("--") + needed + ": required with --cylinder");
  const double d = cl.quantity("diameter", dimension::length), h = cl.quantity("height", dimension::length);
  if (cl.given("level") == cl.given("divisions"))
    throw UsageError("--level: give exactly one of --level and --divisions with --cylinder");
  if (!(d > 0)) throw InputError("--diameter", "", "must be positive");
  if (!(h > 0)) throw InputError("--height", "", "must be positive");
  if (cl.given("level")) {
    const long level = cl.integer("level");
    if (level < 1 || level > 12) throw InputError("--level", "", "must be between 1 and 12");
    return paper_b_cylinder(static_cast<int>(level), d, h);
  }
  CylinderMeshSpec s;
  s.diameter = d;
  s.height = h;
  int n[3];
  char tail;
  if (std::sscanf(cl.text("divisions").c_str(), "%d,%d,%d%c", &n[0], &n[1], &n[2], &tail) != 3 || n[0] < 1 ||
      n[1] < 1 || n[2] < 1 || n[0] > 400 || n[1] > 400 || n[2] > 400)
    throw InputError("--divisions", "", "expected three whole numbers 1-400, e.g. 4,2,8");
  s.core_divisions = n[0], s.ring_divisions = n[1], s.axial_divisions = n[2];
  return s;
}

int run(int argc, char** argv) {
  using namespace latmpm;
  const auto start = std::chrono::steady_clock::now();
  // 1. Options, checked before any work; outputs claimed up front.
  CommandLine cl("latmpm-hexmesh", manual);
  declare_options(cl);
  cl.parse(argc, argv);
  const bool report = !cl.flag_set("quiet");
  const bool cylinder = cl.flag_set("cylinder");
  const bool has_input = !cl.text("input").empty();
  if (cylinder == has_input) throw UsageError("give either a .msh file or --cylinder");
  if (!cl.given("cell")) throw UsageError("--cell: required: the solver's grid cell size, e.g. 0.4mm");
  if (!cl.given("output")) throw UsageError("--output: required: -o FILE (or - for stdout)");
  const double cell = cl.quantity("cell", dimension::length);
  if (!(cell > 0)) throw InputError("--cell", "", "must be positive");
  if (has_input) {
    for (const char* cylinder_only : {"diameter", "height", "level", "divisions", "msh"})
      if (cl.given(cylinder_only)) throw InputError(std::string("--") + cylinder_only, "", "applies only with --cylinder");
    if (!cl.given("units")) throw UsageError("--units: required for a .msh input (its length unit, e.g. mm)");
  } else if (cl.given("units")) {
    throw InputError("--units", "", "applies only to a .msh input");
  }
  const CylinderMeshSpec spec = cylinder ? cylinder_spec(cl) : CylinderMeshSpec{};
  if (cl.text("output") != "-")
    refuse_aliased_outputs({{"--output", cl.text("output")},
                            {"its XDMF view", xdmf_path_beside(cl.text("output"))},
                            {"--msh", cl.text("msh")}});
  OutputFile output(cl.text("output"), "--output");
  std::unique_ptr<OutputFile> xdmf, msh;
  if (!output.to_stdout()) xdmf = std::make_unique<OutputFile>(xdmf_path_beside(output.target()), "--output");
  if (cl.given("msh")) msh = std::make_unique<OutputFile>(cl.text("msh"), "--msh");
  if (report) std::cerr << "latmpm-hexmesh: " << cl.resolved() << "\n";

  // 2. Mesh → points.
  Provenance provenance = Provenance::for_run("latmpm-hexmesh", argc, argv);
  HexMesh mesh;
  // gmsh picks the format by the extension: the mesh is written beside msh's staging file.
  const std::unique_ptr<TemporaryPath> msh_file = msh ? std::make_unique<TemporaryPath>(msh->temp_path() + ".msh") : nullptr;
  if (cylinder) {
    mesh = cylinder_hex_mesh(spec, msh_file ? msh_file->path() : "");
  } else {
    provenance.inputs = {cl.text("input")};
    const double metres_per_unit = parse_quantity("1" + cl.text("units"), dimension::length, "--units");
    mesh = read_hex_mesh(cl.text("input"), metres_per_unit);
  }
  PointSet points = hex_mesh_points(mesh, cl.text("body"), cell);
  if (cylinder) {
    points.parameters["diameter"] = format_millimetres(spec.diameter, 6);
    points.parameters["height"] = format_millimetres(spec.height, 6);
    points.parameters["divisions"] = std::to_string(spec.core_divisions) + "," + std::to_string(spec.ring_divisions) +
                                     "," + std::to_string(spec.axial_divisions);
  }
  points.validate("latmpm-hexmesh");

  // 3. Output: point set with provenance, the XDMF view beside it, the mesh.
  {
    Hdf5File file(output.temp_path(), Hdf5File::Mode::create);
    write_provenance(file, provenance);
    write_point_set(file, points);
    file.close();
  }
  if (xdmf) {
    const std::string target = output.target();
    const std::string h5_name = target.substr(target.find_last_of('/') + 1);
    xdmf->write_text(xdmf_polyvertex(h5_name, points.size(), "/points/position", point_set_xdmf_attributes({})));
  }
  if (msh && std::rename(msh_file->path().c_str(), msh->temp_path().c_str()) != 0)
    throw OutputError(cl.text("msh"), "cannot move the mesh into place");
  output.commit();
  if (xdmf) xdmf->commit();
  if (msh) msh->commit();
  if (report) {
    double volume = 0;
    for (double v : points.volume) volume += v;
    char line[200];
    std::snprintf(line, sizeof line, "  points: %zu hexahedral domains, volume %.6g mm^3, %.2f s\n", points.size(),
                  volume * 1e9, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    std::cerr << line;
  }
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return latmpm::run_tool("latmpm-hexmesh", argc, argv, run); }
