#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/hdf5_file.hpp"
#include "core/provenance.hpp"
#include "run_output/snapshot_writer.hpp"
#include "scratch_dir.hpp"

using namespace latmpm;
namespace fs = std::filesystem;

namespace {

std::string fresh_run_dir(const std::string& name) {
  fs::path d = test::process_scratch("snapshots").path() / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d.string();
}

ParticleSnapshot make_snapshot(size_t n, int64_t step, double time) {
  ParticleSnapshot s;
  s.step = step;
  s.time = time;
  s.resize(n);
  for (size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      s.position[3 * i + k] = 1e-3 * double(i) + 1e-9 * k + 1e-6 * step;
      s.velocity[3 * i + k] = float(k - 1);
    }
    for (int k = 0; k < 6; ++k) s.stress[6 * i + k] = float(1000 * k + i);
    s.von_mises[i] = float(i);
    s.jacobian[i] = 1.0f;
    s.body[i] = int32_t(i % 2);
  }
  s.body_names = {"column", "top_plate"};
  return s;
}

// Every per-point array and the body names equal.
void check_same_points(const ParticleSnapshot& back, const ParticleSnapshot& s) {
  CHECK(back.position == s.position);
  CHECK(back.velocity == s.velocity);
  CHECK(back.stress == s.stress);
  CHECK(back.von_mises == s.von_mises);
  CHECK(back.jacobian == s.jacobian);
  CHECK(back.body == s.body);
  CHECK(back.body_names == s.body_names);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("A snapshot reads back as written, with provenance", "[run_output]") {
  const std::string dir = fresh_run_dir("roundtrip");
  SnapshotWriter writer(dir, Provenance{"latmpm-solve", "0", "cmd", {}, "t", {}});
  ParticleSnapshot s = make_snapshot(5, 40, 2.5e-3);
  const std::string path = writer.write(s);
  CHECK(path == dir + "/snapshots/snap_000040.h5");
  ParticleSnapshot back = read_snapshot(path);
  check_same_points(back, s);
  CHECK(back.step == 40);
  CHECK(back.time == 2.5e-3);
  CHECK(read_provenance(Hdf5File(path, Hdf5File::Mode::read)).tool == "latmpm-solve");
}

TEST_CASE("The XDMF series lists every snapshot in order and its data items match the files", "[run_output]") {
  const std::string dir = fresh_run_dir("xdmf");
  SnapshotWriter writer(dir, Provenance{});
  writer.write(make_snapshot(7, 0, 0));
  writer.write(make_snapshot(7, 10, 1e-3));
  writer.write(make_snapshot(7, 20, 2e-3));
  writer.write(make_snapshot(7, 20, 2e-3));  // the same step again replaces, not appends
  const std::string xmf = read_text(writer.xdmf_path());

  std::regex time_re("<Time Value=\"([^\"]+)\"/>");
  std::vector<double> times;
  for (auto it = std::sregex_iterator(xmf.begin(), xmf.end(), time_re); it != std::sregex_iterator(); ++it)
    times.push_back(std::stod((*it)[1]));
  CHECK(times == std::vector<double>{0, 1e-3, 2e-3});

  // Every DataItem names an existing file and dataset whose shape is the declared one.
  std::regex item_re("Dimensions=\"([0-9 ]+)\"[^>]*>([^:<]+):([^<]+)</DataItem>");
  int items = 0;
  for (auto it = std::sregex_iterator(xmf.begin(), xmf.end(), item_re); it != std::sregex_iterator(); ++it) {
    const std::string file = dir + "/" + (*it)[2].str(), dataset = (*it)[3];
    REQUIRE(fs::exists(file));
    std::vector<size_t> declared;
    std::istringstream ds((*it)[1].str());
    for (size_t d; ds >> d;) declared.push_back(d);
    CHECK(Hdf5File(file, Hdf5File::Mode::read).shape(dataset) == declared);
    ++items;
  }
  CHECK(items == 3 * 6);  // geometry + 5 attributes per frame
}

TEST_CASE("A new run in the same directory starts from no snapshots", "[run_output]") {
  const std::string dir = fresh_run_dir("rerun");
  {
    SnapshotWriter first(dir, Provenance{});
    first.write(make_snapshot(3, 0, 0));
    first.write(make_snapshot(3, 500, 1));
  }
  std::ofstream(dir + "/snapshots/notes.txt") << "keep me";
  SnapshotWriter second(dir, Provenance{});
  CHECK_FALSE(fs::exists(dir + "/snapshots/snap_000500.h5"));
  CHECK_FALSE(fs::exists(second.xdmf_path()));
  CHECK(fs::exists(dir + "/snapshots/notes.txt"));
}

TEST_CASE("A snapshot whose points are written in blocks equals the one written whole", "[run_output]") {
  // As several MPI processes write one: the file laid out for all points, each block of
  // points written into it afterwards (here both blocks by this process).
  const ParticleSnapshot whole = make_snapshot(7, 20, 1e-3);
  auto block = [&](size_t first, size_t count) {
    ParticleSnapshot b = make_snapshot(count, 20, 1e-3);
    for (size_t i = 0; i < count; ++i) {
      std::copy_n(&whole.position[3 * (first + i)], 3, &b.position[3 * i]);
      std::copy_n(&whole.velocity[3 * (first + i)], 3, &b.velocity[3 * i]);
      std::copy_n(&whole.stress[6 * (first + i)], 6, &b.stress[6 * i]);
      b.von_mises[i] = whole.von_mises[first + i], b.jacobian[i] = whole.jacobian[first + i], b.body[i] = whole.body[first + i];
    }
    return b;
  };
  const ParticleSnapshot first = block(0, 3), second = block(3, 4);
  const Provenance provenance{"latmpm-solve", "0", "cmd", {}, "t", {}};
  SnapshotWriter one(fresh_run_dir("whole"), provenance), parts(fresh_run_dir("blocks"), provenance);
  const ParticleSnapshot back_whole = read_snapshot(one.write(whole));
  const std::string path = parts.write_shared(first, 7, [&](const std::string& staged) {
    Hdf5File file(staged, Hdf5File::Mode::read_write);
    write_snapshot_rows(file, first, 0);
    write_snapshot_rows(file, second, 3);
    file.close();
  });
  const ParticleSnapshot back = read_snapshot(path);
  check_same_points(back, back_whole);
  CHECK(back.step == 20);
  REQUIRE(parts.frames().size() == 1);
  CHECK(parts.frames()[0].points == 7);  // the series index counts every process's points
}
