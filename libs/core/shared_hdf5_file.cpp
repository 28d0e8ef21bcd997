#include "core/shared_hdf5_file.hpp"

#include <hdf5.h>

namespace latmpm {

#ifndef H5_HAVE_PARALLEL
#error "the MPI build needs the parallel HDF5 library (libhdf5-openmpi-dev; cmake/LatmpmDependencies.cmake)"
#endif

Hdf5File open_shared_hdf5(const std::string& path, MPI_Comm communicator) {
  const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_mpio(access, communicator, MPI_INFO_NULL);
  // Every process's rows of a dataset in one MPI-IO call (two-phase I/O), not one per process.
  const hid_t transfer = H5Pcreate(H5P_DATASET_XFER);
  H5Pset_dxpl_mpio(transfer, H5FD_MPIO_COLLECTIVE);
  return open_hdf5_with(path, access, transfer);
}

}  // namespace latmpm
