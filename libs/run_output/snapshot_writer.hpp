// Particle snapshots of a run: RUN_DIR/snapshots/snap_<step>.h5 (one HDF5 file each, with
// provenance) and RUN_DIR/snapshots.xmf, the XDMF time series ParaView opens. Each snapshot
// file is written under a temporary name and renamed, and the .xmf is rewritten the same way
// after it, so a run stopped at any moment leaves only whole snapshots, all listed.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/provenance.hpp"
#include "run_output/particle_snapshot.hpp"
#include "run_output/xdmf_time_series.hpp"

namespace latmpm {

class Hdf5File;

class SnapshotWriter {
 public:
  // Creates RUN_DIR/snapshots/ and removes snap_*.h5 and failure.h5 left by an earlier run.
  SnapshotWriter(std::string run_dir, Provenance provenance);
  // A resumed run: keeps the snapshots of these frames (an earlier run's, up to its
  // checkpoint) and removes every other snap_*.h5; new snapshots are added to them.
  SnapshotWriter(std::string run_dir, Provenance provenance, std::vector<XdmfFrame> kept);
  // Writes the snapshot and returns its path. A second snapshot of the same step replaces
  // the first (e.g. the final state when the last regular snapshot fell on the last step).
  std::string write(const ParticleSnapshot& snapshot);
  // The same for a snapshot whose points several MPI processes write (docs/cluster.md,
  // "Output"): `block` holds this (rank 0's) block of the `total` points, in id order from
  // point 0, with the snapshot's time, step and names. The file is laid out here and closed,
  // then fill_rows(its path) has every process write its block (write_snapshot_rows,
  // Domain::write_shared_rows); then it is published and the series index rewritten.
  std::string write_shared(const ParticleSnapshot& block, size_t total,
                           const std::function<void(const std::string&)>& fill_rows);
  // A snapshot outside the time series, RUN_DIR/snapshots/<stem>.h5 with its own
  // RUN_DIR/<stem>.xmf (e.g. "failure": the state when a run stopped, possibly mid-step).
  std::string write_separate(const ParticleSnapshot& snapshot, const std::string& stem);
  const std::vector<XdmfFrame>& frames() const { return frames_; }
  std::string xdmf_path() const { return run_dir_ + "/snapshots.xmf"; }

 private:
  // The whole snapshot, or (fill_rows set) its layout for `total` points, filled by fill_rows.
  void write_file(const ParticleSnapshot& snapshot, const std::string& path, size_t total,
                  const std::function<void(const std::string&)>& fill_rows) const;
  std::string add_frame(const ParticleSnapshot& snapshot, size_t total,
                        const std::function<void(const std::string&)>& fill_rows);
  void write_index(const std::vector<XdmfFrame>& frames, const std::string& path) const;

  std::string run_dir_;
  Provenance provenance_;
  std::vector<XdmfFrame> frames_;
};

// A snapshot's per-point rows [first, first + block.size()) written into a file laid out
// for them (SnapshotWriter::write_shared): on several processes, each its block.
void write_snapshot_rows(Hdf5File& file, const ParticleSnapshot& block, size_t first);

// Reads a snapshot back (tests, post-processing).
ParticleSnapshot read_snapshot(const std::string& path);

}  // namespace latmpm
