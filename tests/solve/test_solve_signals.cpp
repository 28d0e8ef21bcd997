// latmpm-solve stopped by SIGTERM or SIGINT: it finishes the step, saves the checkpoint and
// the series, exits with 128 + the signal, and --resume ends with the files of a run that
// never stopped, byte for byte.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include "scratch_dir.hpp"
#include "solve_tool.hpp"
#include "tiny_column.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

// The tiny column compressed ten times slower and 2.5 times further: thousands of steps.
std::string slow_scene() {
  std::string scene = test::tiny_scene;
  for (auto [from, to] : {std::pair<std::string, std::string>{"\"0.2mm\"", "\"0.5mm\""}, {"-100mm/s", "-10mm/s"},
                          {"series_every = 25", "series_every = 50"}, {"snapshot_every = 100", "snapshot_every = 1000"}})
    scene.replace(scene.find(from), from.size(), to);
  return scene;
}

// Starts latmpm-solve with `args` in `dir` (stdout and stderr to files there); returns its pid.
pid_t start_solve(const fs::path& dir, const std::vector<std::string>& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    const int out = ::open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    const std::string tool = std::string(LATMPM_BIN_DIR) + "/latmpm-solve";
    std::vector<char*> argv{const_cast<char*>(tool.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(tool.c_str(), argv.data());
    ::_exit(127);
  }
  return pid;
}

int wait_status(pid_t pid) {
  int raw = 0;
  ::waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -WTERMSIG(raw);
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

size_t line_count(const fs::path& p) {
  std::ifstream in(p);
  size_t lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

}  // namespace

TEST_CASE("A run stopped by a signal saves a checkpoint and resumes as if never stopped", "[solve][signals]") {
  const int signo = GENERATE(SIGTERM, SIGINT);
  const test::ScratchDir scratch("solve-signals");
  test::write_points(test::tiny_column({}), scratch / "column.h5");
  std::ofstream(scratch / "slow.toml") << slow_scene();

  REQUIRE(wait_status(start_solve(scratch.path(), {"slow.toml", "-o", "whole", "--quiet", "--threads", "1"})) == 0);

  // Stopped mid-run (the series has its rows of steps 0, 50 and 100), resumed with two threads.
  const pid_t pid = start_solve(scratch.path(), {"slow.toml", "-o", "stopped", "--quiet", "--threads", "1"});
  for (int i = 0; i < 5000 && line_count(scratch.path() / "stopped/series.csv") < 4; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ::kill(pid, signo);
  const int status = wait_status(pid);
  INFO(read_text(scratch.path() / "stderr.txt"));
  REQUIRE(status == 128 + signo);
  const fs::path stopped = scratch.path() / "stopped";
  CHECK(fs::exists(stopped / "checkpoint.h5"));
  CHECK_THAT(read_text(stopped / "log.txt"), Catch::Contains("status: interrupted"));
  CHECK(line_count(stopped / "series.csv") < line_count(scratch.path() / "whole/series.csv"));
  CHECK_THAT(read_text(scratch.path() / "stderr.txt"), Catch::Contains("--resume"));
  for (const auto& entry : fs::recursive_directory_iterator(stopped))
    CHECK(entry.path().filename().string().find(".tmp.") == std::string::npos);

  REQUIRE(wait_status(start_solve(scratch.path(), {"--resume", "stopped", "--quiet", "--threads", "2"})) == 0);
  CHECK(read_text(stopped / "series.csv") == read_text(scratch.path() / "whole/series.csv"));
  CHECK(read_text(stopped / "snapshots.xmf") == read_text(scratch.path() / "whole/snapshots.xmf"));
}

TEST_CASE("A static solve stopped by a signal keeps its converged increments and says so", "[solve][signals]") {
  const test::ScratchDir scratch("solve-static-signal");
  test::write_points(test::tiny_column({}), scratch / "column.h5");
  // The tiny column, neo-Hookean, 2 mm in 2000 static increments: far longer than the wait.
  std::string scene = test::tiny_scene;
  for (auto [from, to] : {std::pair<std::string, std::string>{"\"0.2mm\"", "\"2mm\""},
                          {"\"1050kg/m^3\" }", "\"1050kg/m^3\", model = \"neo_hookean\" }"}})
    scene.replace(scene.find(from), from.size(), to);
  scene += "[solver]\nkind = \"static\"\nincrements = 2000\n";
  std::ofstream(scratch / "static.toml") << scene;

  const pid_t pid = start_solve(scratch.path(), {"static.toml", "-o", "stopped", "--quiet"});
  // The header, the start row and two converged increments.
  for (int i = 0; i < 15000 && line_count(scratch.path() / "stopped/series.csv") < 4; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ::kill(pid, SIGTERM);
  const int status = wait_status(pid);
  const fs::path stopped = scratch.path() / "stopped";
  INFO(read_text(scratch.path() / "stderr.txt"));
  REQUIRE(status == 128 + SIGTERM);
  CHECK_THAT(read_text(stopped / "status.toml"), Catch::Contains("status = \"interrupted\""));
  CHECK_THAT(read_text(stopped / "status.toml"), Catch::Contains("exit = 143"));
  CHECK_THAT(read_text(stopped / "log.txt"), Catch::Contains("stopped by SIGTERM after"));
  CHECK_THAT(read_text(stopped / "log.txt"), Catch::Contains("Newton step 1: residual"));
  CHECK_THAT(read_text(scratch.path() / "stderr.txt"), Catch::Contains("stopped by SIGTERM"));
  const size_t rows = line_count(stopped / "series.csv");
  CHECK(rows >= 4);
  CHECK(rows < 2002);
  CHECK(fs::exists(stopped / "series.h5"));
  for (const auto& entry : fs::recursive_directory_iterator(stopped))
    CHECK(entry.path().filename().string().find(".tmp.") == std::string::npos);
}
