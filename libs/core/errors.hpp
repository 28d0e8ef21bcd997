// Typed errors thrown by the libraries. Only a tool's main() catches them and maps each to
// an exit status with one line (see core/tool_main.hpp):
//   UsageError 1, InputError 2, NumericalError 3, OutputError 5.
#pragma once
#include <stdexcept>
#include <string>

namespace latmpm {

// The command line itself is malformed: unknown option, missing value.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Input that cannot be used: names where (file or option), which field, and what is wrong.
struct InputError : std::runtime_error {
  InputError(const std::string& where, const std::string& field, const std::string& problem)
      : std::runtime_error(where + (field.empty() ? "" : ": " + field) + ": " + problem),
        where_(where), field_(field), problem_(problem) {}
  const std::string& where() const { return where_; }
  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string where_, field_, problem_;
};

// The computation went wrong (NaN, inverted element, unstable time step...): the message
// names step, particle and position where known.
struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A NumericalError that every process of a run raises at the same step, decided from sums
// reduced over all of them (the energy checks): the processes can wait for each other before
// they stop, so that rank 0's record of the stop (status.toml, the series) is whole before
// an MPI_Abort ends the job. Any other NumericalError may be one process's alone.
struct CollectiveNumericalError : NumericalError {
  using NumericalError::NumericalError;
};

// An output could not be written (disk full, I/O error, a closed pipe): nothing partial is
// left under the output's name. `where` names the file or option.
struct OutputError : std::runtime_error {
  OutputError(const std::string& where, const std::string& problem) : std::runtime_error(where + ": " + problem) {}
};

// Thrown by the command-line parser after printing --help or --version: exit 0.
struct HelpShown {};

}  // namespace latmpm
