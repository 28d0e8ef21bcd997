// What a tool leaves when it is stopped or its disk is full: signals remove registered
// temporary files and exit 128+N; a write that fails is an OutputError and nothing is
// published; two outputs naming one file are refused. Signals and file-size limits are
// process-wide, so each case runs in a forked child and reports through its exit status.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/hdf5_file.hpp"
#include "core/interruption.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

// Runs `body` in a child process; returns its exit status (-signal if a signal killed it).
int in_child(const std::function<int()>& body) {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(body());
  int raw = 0;
  ::waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -WTERMSIG(raw);
}

// A file-size limit of `bytes` for this process, as a full disk: writes beyond it fail.
void limit_file_size(rlim_t bytes) {
  ::signal(SIGXFSZ, SIG_IGN);
  const rlimit limit{bytes, bytes};
  ::setrlimit(RLIMIT_FSIZE, &limit);
}

}  // namespace

TEST_CASE("SIGTERM and SIGINT remove the staging files and exit with 128 + the signal", "[core][signals]") {
  const test::ScratchDir scratch("interruption");
  const int signo = GENERATE(SIGTERM, SIGINT, SIGHUP);
  const std::string target = scratch / "out.h5";
  const int status = in_child([&] {
    install_signal_handlers("test");
    OutputFile out(target, "-o");
    std::ofstream(out.temp_path()) << "half written";
    ::raise(signo);
    return 0;  // not reached
  });
  CHECK(status == 128 + signo);
  CHECK(fs::is_empty(scratch.path()));
}

TEST_CASE("A deferring run sees the signal between steps; a second signal ends it at once", "[core][signals]") {
  const test::ScratchDir scratch("interruption");
  const int status = in_child([&] {
    install_signal_handlers("test");
    const InterruptionDeferral defer;
    ::raise(SIGTERM);
    if (interruption_signal() != SIGTERM) return 1;
    OutputFile out(scratch / "checkpoint.h5", "checkpoint");
    std::ofstream(out.temp_path()) << "partial";
    ::raise(SIGINT);  // the second signal: out's staging file is removed, exit 130
    return 2;
  });
  CHECK(status == 130);
  CHECK(fs::is_empty(scratch.path()));
}

TEST_CASE("Staging files of a run killed outright are found and removed, other files kept", "[core][signals]") {
  const test::ScratchDir scratch("interruption");
  for (const char* name : {".checkpoint.h5.tmp.a1B2c3", ".series.h5.tmp.XyZ123", "series.csv", ".hidden",
                           "checkpoint.h5", ".x.tmp.short"})
    std::ofstream(scratch / name) << "x";
  CHECK(remove_stale_temporaries(scratch.string()) == 2);
  CHECK(fs::exists(scratch / "series.csv"));
  CHECK(fs::exists(scratch / ".x.tmp.short"));
  CHECK_FALSE(fs::exists(scratch / ".checkpoint.h5.tmp.a1B2c3"));
}

TEST_CASE("A full disk is an OutputError naming the target, and nothing is published", "[core][files]") {
  const test::ScratchDir scratch("disk-full");
  const std::string target = scratch / "big.h5";
  const int status = in_child([&] {
    limit_file_size(16 * 1024);
    try {
      OutputFile out(target, "-o");
      Hdf5File file(out.temp_path(), Hdf5File::Mode::create);
      file.write("/x", std::vector<double>(100000, 1.0), {100000});
      file.close();
      out.commit();
      return 1;  // the write must not succeed
    } catch (const OutputError& e) {
      return std::string(e.what()).rfind(target, 0) == 0 ? 0 : 2;
    } catch (...) {
      return 3;
    }
  });
  CHECK(status == 0);
  CHECK(fs::is_empty(scratch.path()));
}

TEST_CASE("Text written to a full disk is an OutputError", "[core][files]") {
  const test::ScratchDir scratch("disk-full");
  const int status = in_child([&] {
    limit_file_size(1024);
    try {
      write_file_atomically(scratch / "summary.md", std::string(100000, 'x'), "-o");
      return 1;
    } catch (const OutputError&) {
      return 0;
    }
  });
  CHECK(status == 0);
  CHECK(fs::is_empty(scratch.path()));
}

TEST_CASE("Two outputs naming one file are refused, through ./, .., symbolic and hard links", "[core][files]") {
  const test::ScratchDir scratch("aliasing");
  const std::string a = scratch / "a.h5";
  fs::create_directory(scratch / "sub");
  CHECK_THROWS_AS(refuse_aliased_outputs({{"-o", a}, {"--stl", a}}), InputError);
  CHECK_THROWS_AS(refuse_aliased_outputs({{"-o", a}, {"--stl", scratch / "sub/../a.h5"}}), InputError);
  CHECK_THROWS_AS(refuse_aliased_outputs({{"-o", a}, {"--stl", scratch.string() + "/./a.h5"}}), InputError);
  fs::create_symlink(a, scratch / "link.stl");  // dangling: a.h5 does not exist yet
  CHECK_THROWS_WITH(refuse_aliased_outputs({{"-o", a}, {"--stl", scratch / "link.stl"}}),
                    Catch::Contains("--stl " + (scratch / "link.stl") + ": names the same file as -o " + a));
  std::ofstream(scratch / "b.h5") << "x";
  fs::create_hard_link(scratch / "b.h5", scratch / "hard.stl");
  CHECK_THROWS_AS(refuse_aliased_outputs({{"-o", scratch / "b.h5"}, {"--stl", scratch / "hard.stl"}}), InputError);
  // Distinct files, stdout and absent options pass.
  CHECK_NOTHROW(refuse_aliased_outputs({{"-o", a}, {"--stl", scratch / "a.stl"}, {"--step", ""}}));
  CHECK_NOTHROW(refuse_aliased_outputs({{"-o", "-"}, {"--stl", "-"}}));
}
