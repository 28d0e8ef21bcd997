// Checked reads of HDF5 datasets: shape, type, finiteness and range, each refused with one
// message naming the file and the dataset.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "core/checked_read.hpp"
#include "core/errors.hpp"
#include "core/hdf5_file.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;

namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();

// A file with a 4x3 table, a list of ids, a scalar attribute and a list of names.
std::string sample_file(const test::ScratchDir& scratch) {
  const std::string path = scratch / "sample.h5";
  Hdf5File f(path, Hdf5File::Mode::create);
  f.write("/t/position", std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, {4, 3});
  f.write("/t/body", std::vector<int32_t>{0, 1, 1, 0}, {4});
  f.write("/t/mass", std::vector<double>{1, 2, nan, 4}, {4});
  f.write_strings("/t/names", {"a", "b"});
  f.set_attribute("/t", "dt", 1e-6);
  f.set_attribute("/t", "step", int64_t{12});
  f.close();
  return path;
}

}  // namespace

TEST_CASE("A checked read returns a dataset of the expected shape, finite and in range", "[core][hdf5]") {
  const test::ScratchDir scratch("checked-read");
  const Hdf5File f(sample_file(scratch), Hdf5File::Mode::read);
  CHECK(read_checked_doubles(f, "/t/position", {4, 3}).at(11) == 11);
  CHECK(read_checked_doubles(f, "/t/position", {any_extent, 3}, {0, 11}).size() == 12);
  CHECK(read_checked_integers(f, "/t/body", {4}, 0, 1) == std::vector<int64_t>{0, 1, 1, 0});
  CHECK(read_checked_strings(f, "/t/names", 2).at(1) == "b");
  CHECK(read_checked_double_attribute(f, "/t", "dt", {0, 1}) == 1e-6);
  CHECK(read_checked_integer_attribute(f, "/t", "step", 0, 100) == 12);
}

TEST_CASE("A checked read refuses a dataset of another shape, naming file and dataset", "[core][hdf5]") {
  const test::ScratchDir scratch("checked-read");
  const std::string path = sample_file(scratch);
  const Hdf5File f(path, Hdf5File::Mode::read);
  // A few rows short, a column missing, another rank.
  CHECK_THROWS_WITH(read_checked_doubles(f, "/t/position", {5, 3}),
                    path + ": /t/position: shape 4x3, expected 5x3");
  CHECK_THROWS_WITH(read_checked_doubles(f, "/t/position", {any_extent, 4}),
                    path + ": /t/position: shape 4x3, expected Nx4");
  CHECK_THROWS_WITH(read_checked_integers(f, "/t/body", {4, 1}, 0, 1), path + ": /t/body: shape 4, expected 4x1");
  CHECK_THROWS_WITH(read_checked_strings(f, "/t/names", 3), path + ": /t/names: 2 entries, expected 3");
  CHECK_THROWS_AS(read_checked_doubles(f, "/t/none", {1}), InputError);
}

TEST_CASE("A checked read refuses NaN, values out of range and integers stored as reals", "[core][hdf5]") {
  const test::ScratchDir scratch("checked-read");
  const std::string path = sample_file(scratch);
  const Hdf5File f(path, Hdf5File::Mode::read);
  CHECK_THROWS_WITH(read_checked_doubles(f, "/t/mass", {4}), path + ": /t/mass: nan at index 2 (values must be finite)");
  CHECK_THROWS_WITH(read_checked_doubles(f, "/t/position", {4, 3}, {0, 10}),
                    path + ": /t/position: value 11 at row 3 is outside [0, 10]");
  CHECK_THROWS_WITH(read_checked_integers(f, "/t/body", {4}, 0, 0),
                    path + ": /t/body: value 1 at index 1 is outside [0, 0]");
  CHECK_THROWS_WITH(read_checked_integers(f, "/t/position", {4, 3}, 0, 100),
                    path + ": /t/position: not an integer dataset");
  CHECK_THROWS_WITH(read_checked_double_attribute(f, "/t", "dt", {1, 2}),
                    path + ": /t@dt: value 1e-06 is not within [1, 2]");
  CHECK_THROWS_WITH(read_checked_integer_attribute(f, "/t", "step", -5, 0),
                    path + ": /t@step: value 12 is not within [-5, 0]");
}
