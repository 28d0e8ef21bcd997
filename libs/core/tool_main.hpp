// The one place errors become exit statuses. A tool's main() is
//   int main(int argc, char** argv) { return latmpm::run_tool("latmpm-x", argc, argv, run); }
// and prints exactly one line on failure (docs/robustness.md):
//   0 success (or --help), 1 usage, 2 bad input, 3 numerical failure, 4 internal error,
//   5 an output could not be written (disk full, I/O error, closed pipe),
//   128 + N stopped by signal N (130 SIGINT, 143 SIGTERM), temporary files removed.
#pragma once
#include <functional>
#include <string>

namespace latmpm {

enum ExitStatus {
  exit_ok = 0,
  exit_usage = 1,
  exit_bad_input = 2,
  exit_numerical = 3,
  exit_internal = 4,
  exit_output = 5,
  exit_signal_base = 128
};

int run_tool(const std::string& tool, int argc, char** argv,
             const std::function<int(int, char**)>& body);

}  // namespace latmpm
