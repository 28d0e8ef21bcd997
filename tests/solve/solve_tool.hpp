// Helpers of the tool-level tests of latmpm-solve: a scratch directory per test process
// holding the tiny column's points, the tiny scene that runs on it, and a run of the built tool.
#pragma once
#include <filesystem>
#include <string>

namespace latmpm::test {

// A 0.2 mm compression of the tiny column (tiny_column.hpp) at 100 mm/s, uGIMP, cell 1 mm.
extern const char* const tiny_scene;

struct ToolRun {
  int status;
  std::string err, out;
};

// This process's scratch directory, made once, with the tiny column's points as column.h5.
std::filesystem::path scratch();
// Writes TEXT to scratch()/NAME; returns its path.
std::string write_scene(const std::string& name, const std::string& text);
// Runs `latmpm-solve ARGS` from the build, its stdout and stderr captured.
ToolRun run_solve(const std::string& args);
std::string read_text(const std::filesystem::path& path);

}  // namespace latmpm::test
