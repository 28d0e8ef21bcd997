// An XDMF 3 temporal collection over the snapshot files, so ParaView (Xdmf3 reader) plays
// the run: one Polyvertex grid per snapshot whose data items point into the HDF5 file.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace latmpm {

struct XdmfFrame {
  std::string hdf5_file;  // relative to the .xmf file, e.g. "snapshots/snap_000100.h5"
  double time = 0;        // s
  int64_t step = 0;
  size_t points = 0;
  // Per-point scalars beyond the fixed fields (material history: /particles/<name>, float).
  std::vector<std::string> extra_scalars;
};

// The whole .xmf text for these frames, with the fields a ParticleSnapshot writes.
std::string xdmf_time_series(const std::vector<XdmfFrame>& frames);

}  // namespace latmpm
