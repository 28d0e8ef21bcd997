// The command-line parser every tool uses. Options are declared once; the parser rejects
// unknown options (catching typos such as --strut-diamter), prints --help from the
// declarations, and echoes the resolved options so a run can be repeated exactly.
// The tool's manual text should contain sample runs as lines "  $ command ..." : each one
// is run as a CTest smoke test (scripts/run-help-examples.sh).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "core/units.hpp"

namespace latmpm {

class CommandLine {
 public:
  // `manual` is the head of --help: what the tool does and sample runs.
  CommandLine(std::string tool, std::string manual);

  // --name VALUE (or --name=VALUE). An empty default means "not given".
  void option(const std::string& name, const std::string& metavar, const std::string& help,
              const std::string& default_value = "");
  // --name VALUE, may be repeated (e.g. --set key=value).
  void repeated_option(const std::string& name, const std::string& metavar, const std::string& help);
  // --name, no value.
  void flag(const std::string& name, const std::string& help);
  // A one-letter spelling of a declared option: alias('o', "output") accepts "-o PATH"
  // (and "-o=PATH") as "--output PATH".
  void alias(char letter, const std::string& name);
  // A positional argument, in declaration order.
  void positional(const std::string& name, const std::string& help, bool required = true);
  // The last positional: takes every remaining argument (e.g. RUN_DIR...); all(name) lists them.
  void positional_list(const std::string& name, const std::string& help, bool required = true);

  // Throws HelpShown after printing --help/--version, UsageError on malformed input.
  void parse(int argc, const char* const* argv);

  bool given(const std::string& name) const;  // option/positional present, or flag set
  std::string text(const std::string& name) const;  // value or default ("" if none)
  std::vector<std::string> all(const std::string& name) const;  // repeated option values
  // Typed values; errors name the option (exit status 2).
  double quantity(const std::string& name, const Dimension& expected) const;
  long integer(const std::string& name) const;
  double number(const std::string& name) const;  // dimensionless
  bool flag_set(const std::string& name) const { return given(name); }

  const std::string& tool() const { return tool_; }
  int argc() const { return static_cast<int>(argv_.size()); }
  const std::vector<std::string>& argv() const { return argv_; }
  std::string help_text() const;
  // "latmpm-lattice --preset T2P30 --plates 3mm ..." with defaults filled in.
  std::string resolved() const;

 private:
  struct Declared {
    std::string name, metavar, help, default_value;
    enum Kind { value, repeated, boolean, positional } kind;
    bool required = false;
    bool many = false;  // positional_list
  };
  const Declared* find(const std::string& name) const;
  std::string display(const std::string& name) const;

  std::string tool_, manual_;
  std::vector<Declared> declared_;
  std::map<char, std::string> aliases_;  // letter -> option name
  std::map<std::string, std::vector<std::string>> values_;
  std::vector<std::string> argv_;
};

}  // namespace latmpm
