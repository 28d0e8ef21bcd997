// How a file was made: recorded in every file a tool writes (see docs/formats.md).
// Root attributes describe the tool run that wrote the file; the dataset /provenance/history
// carries one line per earlier run in the chain (copied from the inputs), oldest first, so a
// points file still says which lattice command made its geometry.
#pragma once
#include <string>
#include <vector>

namespace latmpm {

class Hdf5File;

const char* version_string();  // "0.1.0+<git hash>", generated at build time

struct Provenance {
  std::string tool;          // "latmpm-lattice"
  std::string version;       // version_string()
  std::string command_line;  // exactly as typed, shell-quoted where needed
  std::vector<std::string> inputs;   // input files ("-" for stdin)
  std::string created_utc;   // ISO 8601
  std::vector<std::string> history;  // earlier runs, oldest first

  // A provenance for this run: tool name, full command line from argv, now.
  static Provenance for_run(const std::string& tool, int argc, const char* const* argv);
  // One line describing this run, as it appears in a later file's history.
  std::string summary_line() const;
  // Appends the history of an input file (its own history plus its own run).
  void inherit_from(const Hdf5File& input);
};

void write_provenance(Hdf5File& file, const Provenance& p);
Provenance read_provenance(const Hdf5File& file);

// Shell-quotes argv into one line that can be pasted back into a shell.
std::string quoted_command_line(int argc, const char* const* argv);

}  // namespace latmpm
