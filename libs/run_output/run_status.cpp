#include "run_output/run_status.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/machine.hpp"

namespace latmpm {
namespace {

// Initialised with the library's other statics, before main(): the wall time of the whole
// process, reading the points and building the solver included.
const auto process_start = std::chrono::steady_clock::now();

rusage self_usage() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage;
}

// A TOML basic string: quotes, backslashes and control characters escaped (TOML 1.0).
std::string toml_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(c));
      quoted += buf;
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

double seconds(const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); }

}  // namespace

double process_cpu_seconds() {
  const rusage u = self_usage();
  return seconds(u.ru_utime) + seconds(u.ru_stime);
}

double process_peak_memory_mb() { return double(self_usage().ru_maxrss) / 1024.0; }  // Linux: kB

double process_wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - process_start).count();
}

RunOutcome outcome_without_run(const std::string& status, int exit_status, const std::string& reason) {
  RunOutcome o;
  o.status = status;
  o.exit_status = exit_status;
  o.reason = reason;
  o.wall_seconds = process_wall_seconds();
  o.cpu_seconds = process_cpu_seconds();
  o.peak_memory_mb = process_peak_memory_mb();
  return o;
}

void write_run_status(const std::string& run_dir, const RunOutcome& o, const Provenance& p) {
  // One flat table in the order of run_status.hpp; numbers to 10 digits, so that a shell can
  // read a key with `sed -n 's/^steps = //p'` and toml++ (latmpm-post) reads it all.
  std::ostringstream text;
  auto key = [&](const char* name) -> std::ostream& { return text << name << " = "; };
  auto number = [&](const char* name, double value) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", value);
    key(name) << buf << "\n";
  };
  text << "# How this latmpm-solve run ended (docs/scene.md, \"The run directory\")\n";
  key("status") << toml_string(o.status) << "\n";
  key("exit") << o.exit_status << "\n";
  key("reason") << toml_string(o.reason) << "\n";
  key("steps") << o.steps << "\n";
  number("simulated_time_s", o.simulated_time);
  key("points") << o.points << "\n";
  number("wall_s", o.wall_seconds);
  number("cpu_s", o.cpu_seconds);
  number("stepping_wall_s", o.stepping_wall_seconds);
  number("updates_per_s", o.updates_per_second);
  number("peak_memory_mb", o.peak_memory_mb);
  key("tool") << toml_string(p.tool) << "\n";
  key("version") << toml_string(p.version) << "\n";
  if (!o.precision.empty()) key("precision") << toml_string(o.precision) << "\n";
  // The machine of this part: a resumed run's earlier parts may have run on another.
  key("cpu_model") << toml_string(cpu_model()) << "\n";
  key("cpus") << usable_cpus() << "\n";
  key("vector_isa") << toml_string(vector_instruction_set()) << "\n";
  key("command") << toml_string(p.command_line) << "\n";
  key("written_utc") << toml_string(Provenance::for_run(p.tool, 0, nullptr).created_utc) << "\n";

  const std::string path = run_dir + "/status.toml";
  OutputFile out(path, path);
  {
    std::ofstream file(out.temp_path(), std::ios::trunc);
    file << text.str();
    if (!file.flush()) throw InputError(path, "", "cannot write (disk full?)");
  }
  out.commit();
}

}  // namespace latmpm
