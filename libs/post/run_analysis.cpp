#include "post/run_analysis.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace latmpm::post {

const char* to_string(TestKind kind) {
  switch (kind) {
    case TestKind::compression: return "compression";
    case TestKind::impact: return "impact";
    case TestKind::column: return "column";
  }
  return "?";
}

namespace {

TestKind choose_kind(const RunDirectory& run, const std::string& requested) {
  if (requested == "compression") return TestKind::compression;
  if (requested == "impact") return TestKind::impact;
  if (requested == "column") return TestKind::column;
  if (requested != "auto")
    throw InputError("--kind", "", "'" + requested + "' is not one of compression, impact, column, auto");
  if (run.series.has("flyer_velocity")) return TestKind::impact;  // whatever the specimen
  if (run.specimen.cell == "column") return TestKind::column;
  return TestKind::compression;
}

bool all_zero(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return x == 0; });
}

std::string choose_load(const RunDirectory& run, TestKind kind, const std::string& requested) {
  const SeriesTable& s = run.series;
  if (!requested.empty()) {
    const std::string name = requested.rfind("load_", 0) == 0 ? requested : "load_" + requested;
    if (!s.has(name))
      throw InputError(run.path + "/series.csv", "--load " + requested, "no column '" + name + "' in this run");
    return name;
  }
  if (kind == TestKind::impact) {
    for (const char* name : {"load_flyer", "load_fixed", "load_driven", "load_record"})
      if (s.has(name)) return name;
  } else {
    for (const char* name : {"load_driven", "load_fixed", "load_record"})
      if (s.has(name) && !all_zero(s.column(name, run.path))) return name;
    for (const char* name : {"load_driven", "load_fixed", "load_record"})
      if (s.has(name)) return name;
  }
  for (const auto& name : s.names)
    if (name.rfind("load_", 0) == 0) return name;
  throw InputError(run.path + "/series.csv", "load_*", "no load column");
}

std::vector<double> optional_column(const SeriesTable& s, const std::string& name) {
  return s.has(name) ? s.column(name, "") : std::vector<double>{};
}

}  // namespace

RunAnalysis analyse_run(RunDirectory run, const AnalysisOptions& options) {
  RunAnalysis a;
  a.kind = choose_kind(run, options.kind);
  a.load_column = choose_load(run, a.kind, options.load);
  const SeriesTable& s = run.series;
  a.notes = s.notes;
  a.notes.insert(a.notes.end(), run.specimen.notes.begin(), run.specimen.notes.end());

  a.history.time = s.column("time", run.path);
  a.history.load = s.column(a.load_column, run.path);
  // Impact runs may record the flyer's travel; every other run the driven plate's.
  const std::string travel = a.kind == TestKind::impact && s.has("flyer_displacement") ? "flyer_displacement" : "displacement";
  a.history.displacement = s.has(travel) ? s.column(travel, run.path) : std::vector<double>(s.rows(), 0.0);
  a.has_travel = s.rows() >= 2 && *std::max_element(a.history.displacement.begin(), a.history.displacement.end()) > 0;
  if (!a.has_travel) a.notes.push_back("no travel in '" + travel + "': no load–displacement curve");
  if (s.rows() == 0) a.notes.push_back("series.csv has no rows");

  const SpecimenFacts& f = run.specimen;
  if (a.kind == TestKind::impact) {
    a.impact_history.time = a.history.time;
    a.impact_history.load = a.history.load;
    a.impact_history.velocity = optional_column(s, "flyer_velocity");
    a.impact_history.kinetic_energy = optional_column(s, "flyer_kinetic_energy");
    a.impact_history.potential_energy = optional_column(s, "flyer_potential_energy");
    a.impact = impact_metrics(a.impact_history);
    a.notes.insert(a.notes.end(), a.impact->notes.begin(), a.impact->notes.end());
  } else if (a.has_travel) {
    a.compression = compression_metrics(a.history, f.gauge_length, f.mass, options.compression, f.footprint_area);
    if (a.kind == TestKind::column) {
      a.column = column_metrics(a.history, f.youngs_modulus, f.strut_diameter, f.strut_length, options.euler_k);
      a.notes.insert(a.notes.end(), a.column->notes.begin(), a.column->notes.end());
    } else {
      a.notes.insert(a.notes.end(), a.compression->notes.begin(), a.compression->notes.end());
    }
  }
  a.run = std::move(run);
  return a;
}

}  // namespace latmpm::post
