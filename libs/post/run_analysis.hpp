// One run analysed: which kind of test it is, which load column stands for "the load", its
// load history and the metrics of its kind. The choices are made here, once, so tables,
// plots and the summary all say the same thing.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "post/column_metrics.hpp"
#include "post/compression_metrics.hpp"
#include "post/impact_metrics.hpp"
#include "post/run_directory.hpp"

namespace latmpm::post {

enum class TestKind { compression, impact, column };
const char* to_string(TestKind kind);

struct AnalysisOptions {
  std::string kind = "auto";  // compression | impact | column | auto
  std::string load;           // a series column (load_driven, load_fixed, ...), "" = automatic
  double euler_k = clamped_clamped_k;
  CompressionSettings compression;
};

struct RunAnalysis {
  RunDirectory run;
  TestKind kind = TestKind::compression;
  std::string load_column;
  LoadHistory history;   // SI; displacement is zero when the series has no travel
  bool has_travel = false;  // a displacement that grows: a load–displacement curve exists
  std::optional<CompressionMetrics> compression;
  std::optional<ColumnMetrics> column;
  std::optional<ImpactMetrics> impact;
  ImpactHistory impact_history;  // flyer columns, when present
  std::vector<std::string> notes;  // the run's own (series, specimen) and the metrics' notes
};

// Kind "auto": impact when the series has flyer_velocity, column when the point files'
// parameters say cell = column, compression otherwise. Load "" (automatic): for impact the first
// of load_flyer, load_fixed, load_driven, load_record present; otherwise the first of
// load_driven, load_fixed, load_record that is not zero throughout.
// Throws InputError(run path, option, problem) for an unknown kind or a load column the run
// does not have.
RunAnalysis analyse_run(RunDirectory run, const AnalysisOptions& options);

}  // namespace latmpm::post
