// An HDF5 file that every process of an MPI run writes at once (parallel HDF5 through
// MPI-IO): one process lays the file out (Hdf5File::reserve), closes it, and then every
// process opens it here and writes its own rows (Hdf5File::write_rows, collective
// transfers). Only in a build with -DLATMPM_MPI=ON, which links Debian's parallel HDF5
// (libhdf5-openmpi-dev) instead of the serial one (docs/cluster.md, "Output").
#pragma once
#include <mpi.h>

#include <string>

#include "core/hdf5_file.hpp"

namespace latmpm {

// Opens the existing file `path` on every process of `communicator` (collective: every
// process calls it with the same path). Its metadata (groups, datasets, attributes) is
// fixed: write_rows only. Close it with close() on every process.
Hdf5File open_shared_hdf5(const std::string& path, MPI_Comm communicator);

}  // namespace latmpm
