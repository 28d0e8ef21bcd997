#include "run_output/snapshot_writer.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "core/file_transfer.hpp"
#include "core/hdf5_file.hpp"

namespace fs = std::filesystem;

namespace latmpm {

void ParticleSnapshot::resize(size_t n) {
  position.resize(3 * n);
  velocity.resize(3 * n);
  stress.resize(6 * n);
  von_mises.resize(n);
  jacobian.resize(n);
  body.resize(n);
}

namespace {

// Creates RUN_DIR/snapshots/ and removes what an earlier run left there: every snap_*.h5
// not among `kept`, and the failure state.
void prepare_snapshot_directory(const std::string& run_dir, const std::vector<XdmfFrame>& kept) {
  const fs::path dir = fs::path(run_dir) / "snapshots";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw InputError(dir.string(), "", "cannot create the snapshot directory: " + ec.message());
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("snap_", 0) != 0 || entry.path().extension() != ".h5") continue;
    bool keep = false;
    for (const auto& f : kept) keep = keep || fs::path(f.hdf5_file).filename() == entry.path().filename();
    if (!keep) fs::remove(entry.path());
  }
  fs::remove(dir / "failure.h5", ec);  // a failed earlier run's state
  fs::remove(fs::path(run_dir) / "failure.xmf", ec);
}

}  // namespace

SnapshotWriter::SnapshotWriter(std::string run_dir, Provenance provenance)
    : run_dir_(std::move(run_dir)), provenance_(std::move(provenance)) {
  prepare_snapshot_directory(run_dir_, {});
  std::error_code ec;
  fs::remove(xdmf_path(), ec);
}

SnapshotWriter::SnapshotWriter(std::string run_dir, Provenance provenance, std::vector<XdmfFrame> kept)
    : run_dir_(std::move(run_dir)), provenance_(std::move(provenance)), frames_(std::move(kept)) {
  prepare_snapshot_directory(run_dir_, frames_);
  write_index(frames_, xdmf_path());
}

namespace {
// The per-point datasets of a snapshot, each with its values per point; visit(name, values, columns).
template <class Snapshot, class Visit>
void for_each_point_dataset(Snapshot& s, Visit&& visit) {
  visit("/particles/position", s.position, 3);
  visit("/particles/velocity", s.velocity, 3);
  visit("/particles/stress", s.stress, 6);
  visit("/particles/von_mises", s.von_mises, 1);
  visit("/particles/J", s.jacobian, 1);
  visit("/particles/body", s.body, 1);
  for (auto& scalar : s.extra_scalars) visit("/particles/" + scalar.name, scalar.values, 1);
}
}  // namespace

void write_snapshot_rows(Hdf5File& file, const ParticleSnapshot& block, size_t first) {
  const std::vector<RowBlock> rows{{first, block.size()}};
  for_each_point_dataset(block, [&](const std::string& name, const auto& values, size_t) {
    file.write_rows(name, values, rows);
  });
}

void SnapshotWriter::write_file(const ParticleSnapshot& s, const std::string& path, size_t total,
                                const std::function<void(const std::string&)>& fill_rows) const {
  OutputFile out(path, path);
  {
    Hdf5File file(out.temp_path(), Hdf5File::Mode::create);
    write_provenance(file, provenance_);
    for_each_point_dataset(s, [&](const std::string& name, const auto& values, size_t columns) {
      const std::vector<size_t> dims = columns == 1 ? std::vector<size_t>{total} : std::vector<size_t>{total, columns};
      if (fill_rows)
        file.reserve<typename std::decay_t<decltype(values)>::value_type>(name, dims);
      else
        file.write(name, values, dims);
    });
    file.write_strings("/particles/body_names", s.body_names);
    file.set_attribute("/particles", "time", s.time);
    file.set_attribute("/particles", "step", int64_t(s.step));
    file.set_attribute("/particles/stress", "components", "xx xy xz yy yz zz");
    file.close();
  }
  if (fill_rows) fill_rows(out.temp_path());
  out.commit();
}

void SnapshotWriter::write_index(const std::vector<XdmfFrame>& frames, const std::string& path) const {
  write_file_atomically(path, xdmf_time_series(frames), path);
}

namespace {
std::vector<std::string> extra_scalar_names(const ParticleSnapshot& s) {
  std::vector<std::string> names;
  for (const auto& scalar : s.extra_scalars) names.push_back(scalar.name);
  return names;
}
}  // namespace

std::string SnapshotWriter::write(const ParticleSnapshot& s) { return add_frame(s, s.size(), nullptr); }

std::string SnapshotWriter::write_shared(const ParticleSnapshot& block, size_t total,
                                         const std::function<void(const std::string&)>& fill_rows) {
  return add_frame(block, total, fill_rows);
}

std::string SnapshotWriter::add_frame(const ParticleSnapshot& s, size_t total,
                                      const std::function<void(const std::string&)>& fill_rows) {
  char name[32];
  std::snprintf(name, sizeof name, "snap_%06lld.h5", static_cast<long long>(s.step));
  const std::string relative = std::string("snapshots/") + name;
  write_file(s, run_dir_ + "/" + relative, total, fill_rows);
  if (!frames_.empty() && frames_.back().step == s.step) frames_.pop_back();
  frames_.push_back({relative, s.time, s.step, total, extra_scalar_names(s)});
  write_index(frames_, xdmf_path());
  return run_dir_ + "/" + relative;
}

std::string SnapshotWriter::write_separate(const ParticleSnapshot& s, const std::string& stem) {
  const std::string relative = "snapshots/" + stem + ".h5";
  write_file(s, run_dir_ + "/" + relative, s.size(), nullptr);
  write_index({{relative, s.time, s.step, s.size(), extra_scalar_names(s)}}, run_dir_ + "/" + stem + ".xmf");
  return run_dir_ + "/" + relative;
}

ParticleSnapshot read_snapshot(const std::string& path) {
  Hdf5File file(path, Hdf5File::Mode::read);
  ParticleSnapshot s;
  s.position = file.read_doubles("/particles/position");
  s.velocity = file.read_floats("/particles/velocity");
  s.stress = file.read_floats("/particles/stress");
  s.von_mises = file.read_floats("/particles/von_mises");
  s.jacobian = file.read_floats("/particles/J");
  s.body = file.read_int32("/particles/body");
  s.body_names = file.read_strings("/particles/body_names");
  s.time = file.double_attribute("/particles", "time");
  s.step = file.int_attribute("/particles", "step");
  return s;
}

}  // namespace latmpm
