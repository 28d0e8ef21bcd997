// One latmpm-solve run directory as post-processing sees it (docs/scene.md, "The run
// directory"): its series, how it ended (status.toml; the last status line of log.txt for a
// run directory written before status.toml existed), and the specimen facts
// from its resolved scene. A directory without series.csv, scene.toml and log.txt is not a
// run: InputError naming it (exit 2). A run that failed or never finished is still read — its
// status says so, and every table and plot marks it.
#pragma once
#include <string>
#include <vector>

#include "post/series_table.hpp"
#include "post/specimen.hpp"

namespace latmpm::post {

enum class RunStatus {
  finished,    // "status: finished ..."
  max_steps,   // "status: max_steps ...": stopped by the step limit before the end condition
  failed,      // "status: failed ...": numerical failure, the series holds the rows before it
  unfinished,  // no status line: still running, or killed
};
const char* to_string(RunStatus status);
// Whether the curve covers the whole run the scene asked for.
inline bool complete(RunStatus status) { return status == RunStatus::finished; }

struct RunDirectory {
  std::string path;   // as given
  std::string label;  // legend and file-name stem
  RunStatus status = RunStatus::unfinished;
  std::string status_line;  // the log's status line, or why there is none
  std::string stop_reason;  // the log's "stopped: ..." line, if any
  SeriesTable series;
  SpecimenFacts specimen;
};

// Reads RUN_DIR. Throws InputError(path, "", "not a run directory: ...") when a file is
// missing, and the file's own InputError when series.csv or scene.toml is malformed.
RunDirectory read_run_directory(const std::string& path);

// The run's status from RUN_DIR/status.toml (latmpm-solve; InputError when it is malformed):
// finished, max_steps, failed (also "error"); running, interrupted and bad_input are unfinished.
RunStatus read_run_status_file(const std::string& path, std::string* status_line = nullptr,
                               std::string* stop_reason = nullptr);
// The run's status from the text of log.txt (its last "status:" line).
RunStatus parse_run_status(const std::string& log_text, std::string* status_line = nullptr,
                           std::string* stop_reason = nullptr);

// Legends and file stems for a list of runs: the directory's base name, unless given
// (`explicit_labels[i]` non-empty); duplicates get the parent directory's name prepended, then
// a number. Never empty.
std::vector<std::string> default_labels(const std::vector<std::string>& paths,
                                        const std::vector<std::string>& explicit_labels);
// A label made safe as a file name: letters, digits, '.', '-', '_' kept, others become '_'.
std::string file_stem(const std::string& label);

}  // namespace latmpm::post
