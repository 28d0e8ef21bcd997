#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"
#include "run_output/run_log.hpp"
#include "run_output/series_writer.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

std::string scratch(const std::string& name) {
  return test::process_scratch("run-output") / name;
}

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

Provenance test_provenance() {
  return Provenance{"latmpm-solve", "0.1.0", "latmpm-solve s.toml -o run", {"s.toml"}, "2024-01-01T00:00:00Z", {}};
}

const std::vector<SeriesColumn> columns = {
    {"time", "s", "simulated time"}, {"displacement", "m", "plate travel"}, {"load", "N", "load"}};

}  // namespace

TEST_CASE("Series rows are on disk as soon as they are appended, headers with units", "[run_output]") {
  const std::string csv = scratch("a.csv"), h5 = scratch("a.h5");
  SeriesWriter series(csv, h5, columns, test_provenance());
  CHECK(lines_of(csv) == std::vector<std::string>{"time[s],displacement[m],load[N]"});
  series.append({0.1, 1e-4, -3.25});
  // Read while the writer is still open: the row must already be there.
  auto lines = lines_of(csv);
  REQUIRE(lines.size() == 2);
  CHECK(lines[1] == "0.10000000000000001,0.0001,-3.25");
  CHECK_THROWS(series.append({1, 2}));
}

TEST_CASE("The HDF5 series holds exactly the CSV's values, with units and provenance", "[run_output]") {
  const std::string csv = scratch("b.csv"), h5 = scratch("b.h5");
  SeriesWriter series(csv, h5, columns, test_provenance());
  for (int i = 0; i < 7; ++i) series.append({i * 1e-3 / 3, std::sqrt(double(i)) * 1e-5, -std::exp(i)});
  series.save();

  // The CSV, parsed with strtod, against the HDF5 datasets: bit-identical doubles.
  auto lines = lines_of(csv);
  REQUIRE(lines.size() == 8);
  Hdf5File f(h5, Hdf5File::Mode::read);
  for (size_t c = 0; c < columns.size(); ++c) {
    auto values = f.read_doubles("/series/" + columns[c].name);
    REQUIRE(values.size() == 7);
    for (size_t r = 0; r < 7; ++r) {
      std::stringstream row(lines[r + 1]);
      std::string cell;
      for (size_t k = 0; k <= c; ++k) std::getline(row, cell, ',');
      CHECK(std::strtod(cell.c_str(), nullptr) == values[r]);
    }
    CHECK(f.string_attribute("/series/" + columns[c].name, "unit") == columns[c].unit);
  }
  CHECK(f.read_strings("/series/columns") == std::vector<std::string>{"time[s]", "displacement[m]", "load[N]"});
  CHECK(read_provenance(f).command_line == "latmpm-solve s.toml -o run");

  // A later save replaces the file with the longer series.
  series.append({1, 1, 1});
  series.save();
  Hdf5File again(h5, Hdf5File::Mode::read);
  CHECK(again.read_doubles("/series/time").size() == 8);
}

TEST_CASE("The run log stamps and flushes every line", "[run_output]") {
  const std::string path = scratch("log.txt");
  RunLog log(path);
  log.line("first");
  log.line("second");
  auto lines = lines_of(path);
  REQUIRE(lines.size() == 2);
  CHECK_THAT(lines[0], Catch::StartsWith("[") && Catch::EndsWith("s] first"));
  CHECK_THAT(lines[1], Catch::EndsWith("second"));
}
