// latmpm-imperfect: printing imperfections. Shape perturbations of paper A Sec. 5.3 (types
// A-D) and the column imperfection a sin(n pi z / L) act on point sets; statistical strut
// defects (diameter scatter, waviness, node jitter, missing struts) act on strut graphs.
// Definitions and sources: docs/imperfections.md.
#include <iostream>

#include "core/command_line.hpp"
#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/hdf5_file.hpp"
#include "core/progress.hpp"
#include "core/provenance.hpp"
#include "core/tool_main.hpp"
#include "imperfect/imperfection_plan.hpp"

namespace {

const char* manual = R"(latmpm-imperfect: add printing imperfections to a point set or a strut graph.

Point sets (after latmpm-voxelize) take the shape perturbations of paper A Sec. 5.3:
  A slant-top-layer  the top cell layer sheared sideways, the top base carried with it
  B slant-lattice    the whole print sheared, bases included, linear in height
  C curved-top-base  the top base bent: a flat plate on its crest has a gap 'amount' at the edges
  D bowed-lattice    a half-sine bow between the bases, largest at mid-height
  sine               a column's u0(z) = a sin(n pi (z - z0) / L)   (paper A Sec. 4)
The amount is the largest displacement of any point (default 1.28 mm, the paper's value);
points of bodies not moved keep their exact positions; volumes never change.
Strut graphs (from latmpm-lattice) take seeded statistical defects: diameter scatter,
waviness, node jitter and missing struts. Several perturbations in one call apply in the
order given; each is recorded in /imperfections and /provenance/history.

Sample runs:
  $ latmpm-lattice --preset T1P40 -o t1p40.h5
  $ latmpm-imperfect t1p40.h5 --strut-diameter-cov 5% --waviness 1% --seed 1 -o t1p40-defects.h5
  $ latmpm-voxelize t1p40.h5 --cell 0.64mm --ppc 2 -o - | latmpm-imperfect - --type C --amount 1.28mm -o t1p40-C.h5
)";

int run(int argc, char** argv) {
  using namespace latmpm;
  // 1. Options.
  CommandLine cl("latmpm-imperfect", manual);
  cl.positional("input", "point-set or strut-graph file (HDF5), - for stdin");
  cl.option("output", "PATH", "output file, - for stdout");
  cl.alias('o', "output");
  declare_imperfection_options(cl);
  cl.flag("quiet", "no report on stderr");
  cl.parse(argc, argv);
  if (!cl.given("output")) throw UsageError("missing --output PATH (-o -, for stdout)");
  const ImperfectionPlan plan = plan_from_command_line(cl);
  if (plan.steps.empty()) throw UsageError("nothing to do: give --type or a strut defect option (see --help)");
  const bool report = !cl.flag_set("quiet");

  // 2. Read the input and its provenance.
  InputFile in(cl.text("input"), "input");
  Hdf5File input(in.path(), Hdf5File::Mode::read);
  Provenance provenance = Provenance::for_run("latmpm-imperfect", argc, argv);
  provenance.inputs = {in.source()};
  provenance.inherit_from(input);
  std::vector<std::string> records;
  if (input.exists("/imperfections")) records = input.read_strings("/imperfections");

  // 3. Apply the steps and 4. write the result (under a temporary name until complete).
  OutputFile out(cl.text("output"), "--output");
  Progress progress("imperfections", static_cast<double>(plan.steps.size()), report);
  ImperfectionRun result;
  Hdf5File output(out.temp_path(), Hdf5File::Mode::create);
  if (holds_point_set(input)) {
    PointSet points = read_point_set(input);
    result = apply_plan(points, plan, in.display_name());
    write_point_set(output, points);
  } else if (holds_strut_graph(input)) {
    MemberGraph graph{read_strut_graph(input), {}};
    graph.member = read_strut_members(input, graph.graph);
    result = apply_plan(graph, plan, in.display_name());
    write_strut_graph(output, graph.graph);
    write_strut_members(output, graph.member);
  } else {
    throw InputError(in.display_name(), "", "holds neither a point set (/points) nor a strut graph (/geometry)");
  }
  for (const auto& record : result.records) {
    records.push_back(record);
    provenance.history.push_back(provenance.created_utc + " latmpm-imperfect " + provenance.version + ": " + record);
  }
  write_provenance(output, provenance);
  output.write_strings("/imperfections", records);
  output.close();
  out.commit();
  progress.finish();

  // 5. Report: the resolved options (to repeat the run exactly) and what each step did.
  if (report) {
    // The command as typed (the order of the options matters), with the seed made explicit.
    std::cerr << "latmpm-imperfect: " << quoted_command_line(argc, argv)
              << (cl.given("seed") ? "" : " --seed " + cl.text("seed")) << "\n";
    for (const auto& record : result.records) std::cerr << "  " << record << "\n";
    for (const auto& note : result.notes) std::cerr << "  note: " << note << "\n";
  }
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) { return latmpm::run_tool("latmpm-imperfect", argc, argv, run); }
