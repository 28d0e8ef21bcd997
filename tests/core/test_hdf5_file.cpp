#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {
std::string scratch(const std::string& name) {
  return test::process_scratch("core") / name;
}
}  // namespace

TEST_CASE("HDF5 datasets and attributes round-trip exactly", "[core][hdf5]") {
  const std::string path = scratch("roundtrip.h5");
  std::vector<double> positions{0.1, 0.2, 0.3, 1e-300, -4.5e12, 1.0 / 3.0};
  std::vector<int32_t> ids{7, -3};
  std::vector<uint8_t> tags{0, 255, 17};
  std::vector<std::string> names{"lattice", "bottom plate", "µ-unicode"};
  {
    Hdf5File f(path, Hdf5File::Mode::create);
    f.write("/points/position", positions, {2, 3});
    f.write("/points/body", ids, {2});
    f.write("/tags/x", tags, {3});
    f.write_strings("/bodies/names", names);
    f.set_attribute("/points", "cell_size", 0.00064);
    f.set_attribute("/points", "ppc", int64_t{2});
    f.set_attribute("/", "note", "hello");
    f.set_attribute("/", "origin", std::vector<double>{1, 2, 3});
  }
  Hdf5File f(path, Hdf5File::Mode::read);
  std::vector<size_t> dims;
  CHECK(f.read_doubles("/points/position", &dims) == positions);
  CHECK(dims == std::vector<size_t>{2, 3});
  CHECK(f.read_int32("/points/body") == ids);
  CHECK(f.read_uint8("/tags/x") == tags);
  CHECK(f.read_strings("/bodies/names") == names);
  CHECK(f.double_attribute("/points", "cell_size") == 0.00064);
  CHECK(f.int_attribute("/points", "ppc") == 2);
  CHECK(f.string_attribute("/", "note") == "hello");
  CHECK(f.doubles_attribute("/", "origin") == std::vector<double>{1, 2, 3});
  CHECK_FALSE(f.exists("/nothing/here"));
  CHECK_THROWS_AS(f.read_doubles("/nothing/here"), InputError);
  CHECK_THROWS_WITH(f.double_attribute("/points", "missing"), Catch::Contains("missing attribute"));
}

TEST_CASE("A dataset laid out first and written in blocks of rows equals one written whole", "[core][hdf5]") {
  const std::string path = scratch("rows.h5");
  // Five rows of three; two "processes" write rows {0, 3, 4} and {1, 2}, as blocks.
  std::vector<double> whole(15);
  for (size_t i = 0; i < whole.size(); ++i) whole[i] = 0.1 * double(i) + 1e-17;
  const std::vector<int64_t> ids{10, 11, 12, 13, 14};
  {
    Hdf5File f(path, Hdf5File::Mode::create);
    f.reserve<double>("/p/position", {5, 3});
    f.reserve<int64_t>("/p/id", {5});
    f.reserve<int64_t>("/p/none", {0, 7});
    f.close();
  }
  {
    Hdf5File f(path, Hdf5File::Mode::read_write);
    const std::vector<double> first(whole.begin(), whole.begin() + 3), rest(whole.begin() + 9, whole.end());
    std::vector<double> mine = first;
    mine.insert(mine.end(), rest.begin(), rest.end());
    f.write_rows("/p/position", mine, {{0, 1}, {3, 2}});
    f.write_rows("/p/position", std::vector<double>(whole.begin() + 3, whole.begin() + 9), {{1, 2}});
    f.write_rows("/p/id", std::vector<int64_t>{10, 13, 14}, {{0, 1}, {3, 2}});
    f.write_rows("/p/id", std::vector<int64_t>{11, 12}, {{1, 2}});
    f.write_rows("/p/none", std::vector<int64_t>{}, {});  // a process with nothing to write
    // Rows must come in file order, within the dataset, and match the data.
    CHECK_THROWS_WITH(f.write_rows("/p/id", std::vector<int64_t>{1, 2}, {{3, 1}, {0, 1}}),
                      Catch::Contains("out of order"));
    CHECK_THROWS_WITH(f.write_rows("/p/id", std::vector<int64_t>{1, 2}, {{4, 2}}), Catch::Contains("beyond"));
    CHECK_THROWS(f.write_rows("/p/id", std::vector<int64_t>{1}, {{0, 2}}));
    f.close();
  }
  Hdf5File f(path, Hdf5File::Mode::read);
  std::vector<size_t> dims;
  CHECK(f.read_doubles("/p/position", &dims) == whole);
  CHECK(dims == std::vector<size_t>{5, 3});
  CHECK(f.read_int64("/p/id") == ids);
  CHECK(f.shape("/p/none") == std::vector<size_t>{0, 7});
}

TEST_CASE("Opening a non-HDF5 or missing file is an input error naming it", "[core][hdf5]") {
  const std::string path = scratch("not-hdf5.h5");
  { std::ofstream(path) << "solid nothing\n"; }
  CHECK_THROWS_WITH(Hdf5File(path, Hdf5File::Mode::read), Catch::Contains(path) && Catch::Contains("not an HDF5 file"));
  CHECK_THROWS_WITH(Hdf5File(scratch("missing.h5"), Hdf5File::Mode::read), Catch::Contains("cannot open"));
}

TEST_CASE("Provenance is written, read back and inherited", "[core][provenance]") {
  const char* argv1[] = {"latmpm-lattice", "--preset", "T2P30", "--note", "two words", "-o", "a.h5"};
  Provenance first = Provenance::for_run("latmpm-lattice", 7, argv1);
  CHECK(first.command_line == "latmpm-lattice --preset T2P30 --note 'two words' -o a.h5");
  CHECK(first.version == std::string(version_string()));
  const std::string a = scratch("prov-a.h5");
  {
    Hdf5File f(a, Hdf5File::Mode::create);
    write_provenance(f, first);
  }
  const char* argv2[] = {"latmpm-voxelize", "a.h5"};
  Provenance second = Provenance::for_run("latmpm-voxelize", 2, argv2);
  second.inputs = {"a.h5"};
  {
    Hdf5File f(a, Hdf5File::Mode::read);
    second.inherit_from(f);
    Provenance back = read_provenance(f);
    CHECK(back.tool == "latmpm-lattice");
    CHECK(back.command_line == first.command_line);
    CHECK(back.created_utc == first.created_utc);
  }
  REQUIRE(second.history.size() == 1);
  CHECK_THAT(second.history[0], Catch::Contains("latmpm-lattice --preset T2P30"));
}

TEST_CASE("Output files appear only on commit", "[core][files]") {
  const std::string target = scratch("out.h5");
  fs::remove(target);
  {
    OutputFile out(target, "-o");
    Hdf5File f(out.temp_path(), Hdf5File::Mode::create);
    f.set_attribute("/", "x", 1.0);
    // no commit: as if the run failed
  }
  CHECK_FALSE(fs::exists(target));
  for (auto& e : fs::directory_iterator(fs::path(target).parent_path()))
    CHECK(e.path().filename().string().find(".out.h5.tmp") == std::string::npos);
  {
    OutputFile out(target, "-o");
    { Hdf5File f(out.temp_path(), Hdf5File::Mode::create); }
    out.commit();
  }
  CHECK(fs::exists(target));
  // Finished files get the usual permissions (0666 less the umask), not mkstemp's 0600.
  mode_t mask = ::umask(0);
  ::umask(mask);
  CHECK((fs::status(target).permissions() & fs::perms::all) == static_cast<fs::perms>(0666 & ~mask));
  CHECK_THROWS_WITH(OutputFile("/nonexistent-dir/x.h5", "-o"), Catch::Contains("does not exist"));
}
