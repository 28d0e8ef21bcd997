#include <catch2/catch.hpp>

#include "core/command_line.hpp"
#include "core/errors.hpp"

using namespace latmpm;

namespace {
CommandLine make() {
  CommandLine cl("latmpm-demo", "demo tool\n  $ latmpm-demo --size 2mm\n");
  cl.option("size", "LENGTH", "a length", "1mm");
  cl.option("count", "N", "a count");
  cl.repeated_option("set", "KEY=VALUE", "override");
  cl.flag("force", "do it");
  cl.positional("input", "input file", false);
  return cl;
}
}  // namespace

TEST_CASE("Options parse with defaults, inline values and repeats", "[core][cli]") {
  CommandLine cl = make();
  const char* argv[] = {"latmpm-demo", "in.h5", "--size=2.5mm", "--set", "a=1", "--set", "b=2", "--force"};
  cl.parse(8, argv);
  CHECK(cl.quantity("size", dimension::length) == Approx(0.0025));
  CHECK(cl.all("set") == std::vector<std::string>{"a=1", "b=2"});
  CHECK(cl.flag_set("force"));
  CHECK_FALSE(cl.given("count"));
  CHECK(cl.text("input") == "in.h5");
  CHECK(cl.resolved() == "latmpm-demo --size 2.5mm --set a=1 --set b=2 --force in.h5");
}

TEST_CASE("Command-line errors name the option", "[core][cli]") {
  {
    CommandLine cl = make();
    const char* argv[] = {"latmpm-demo", "--sise", "2mm"};
    CHECK_THROWS_WITH(cl.parse(3, argv), Catch::Contains("unknown option '--sise'"));
  }
  {
    CommandLine cl = make();
    const char* argv[] = {"latmpm-demo", "--size"};
    CHECK_THROWS_AS(cl.parse(2, argv), UsageError);
  }
  {
    CommandLine cl = make();
    const char* argv[] = {"latmpm-demo", "--size", "2"};
    cl.parse(3, argv);
    CHECK_THROWS_WITH(cl.quantity("size", dimension::length), Catch::Contains("--size") && Catch::Contains("no unit"));
  }
  {
    CommandLine cl = make();
    const char* argv[] = {"latmpm-demo", "--count", "2.5"};
    cl.parse(3, argv);
    CHECK_THROWS_WITH(cl.integer("count"), Catch::Contains("--count") && Catch::Contains("whole number"));
  }
  {
    CommandLine cl = make();
    const char* argv[] = {"latmpm-demo", "a", "b"};
    CHECK_THROWS_WITH(cl.parse(3, argv), Catch::Contains("unexpected argument 'b'"));
  }
}

TEST_CASE("Help lists every option with its default", "[core][cli]") {
  CommandLine cl = make();
  std::string help = cl.help_text();
  CHECK_THAT(help, Catch::Contains("--size LENGTH") && Catch::Contains("[default: 1mm]") &&
                       Catch::Contains("  $ latmpm-demo --size 2mm"));
}

TEST_CASE("A one-letter alias stands for its option", "[core]") {
  CommandLine cl("latmpm-demo", "demo\n");
  cl.option("output", "PATH", "where to write");
  cl.alias('o', "output");
  cl.positional("input", "input file");
  SECTION("separate value") {
    const char* argv[] = {"latmpm-demo", "-o", "out.h5", "in.h5"};
    cl.parse(4, argv);
    CHECK(cl.text("output") == "out.h5");
    CHECK(cl.text("input") == "in.h5");
  }
  SECTION("attached value, and - still means a pipe") {
    const char* argv[] = {"latmpm-demo", "-o=-", "-"};
    cl.parse(3, argv);
    CHECK(cl.text("output") == "-");
    CHECK(cl.text("input") == "-");
  }
  SECTION("other letters stay unknown") {
    const char* argv[] = {"latmpm-demo", "-x", "in.h5"};
    CHECK_THROWS_AS(cl.parse(3, argv), UsageError);
  }
  CHECK_THAT(cl.help_text(), Catch::Contains("-o, --output PATH"));
}
