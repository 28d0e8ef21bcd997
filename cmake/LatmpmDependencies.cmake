# All dependencies are Debian packages (scripts/install-deps.sh); nothing is vendored.
# Facts: ../shared/DEBIAN-STACK.md.
list(APPEND CMAKE_MODULE_PATH /usr/lib/x86_64-linux-gnu/cmake/OpenVDB /usr/lib/cmake/OpenVDB)

find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(TBB REQUIRED)
find_package(OpenVDB REQUIRED)            # find-module shipped by libopenvdb-dev
# HDF5: the serial library (libhdf5-dev), except in the MPI build (-DLATMPM_MPI=ON), which
# writes one file from every process and links the parallel one (libhdf5-openmpi-dev,
# h5pcc) instead: one program links one of the two, their symbols are the same.
if(LATMPM_MPI)
  find_program(LATMPM_HDF5_PARALLEL_WRAPPER NAMES h5pcc h5pcc.openmpi)
  if(NOT LATMPM_HDF5_PARALLEL_WRAPPER)
    message(FATAL_ERROR "LATMPM_MPI=ON needs the parallel HDF5 (h5pcc not found): bash scripts/install-deps.sh "
                        "(Debian: libhdf5-openmpi-dev)")
  endif()
  # A build directory configured before found the serial library and cached it: find again.
  if(NOT "${HDF5_C_COMPILER_EXECUTABLE}" STREQUAL "${LATMPM_HDF5_PARALLEL_WRAPPER}")
    get_cmake_property(cached CACHE_VARIABLES)
    foreach(variable IN LISTS cached)
      if(variable MATCHES "^HDF5_")
        unset(${variable} CACHE)
      endif()
    endforeach()
    set(HDF5_C_COMPILER_EXECUTABLE ${LATMPM_HDF5_PARALLEL_WRAPPER} CACHE FILEPATH "HDF5 C compiler wrapper (parallel)")
  endif()
  set(HDF5_PREFER_PARALLEL ON)
endif()
find_package(HDF5 REQUIRED COMPONENTS C)  # needs the C language enabled
if(LATMPM_MPI AND NOT HDF5_IS_PARALLEL)
  message(FATAL_ERROR "LATMPM_MPI=ON: the HDF5 found (${HDF5_C_LIBRARIES}) is not the parallel one")
endif()
find_package(CGAL REQUIRED)
find_package(Threads REQUIRED)

# latmpm::NAME over a library and header directory found by hand, for packages that ship no
# CMake package.
function(latmpm_interface_target name library include_dir)
  if(NOT TARGET latmpm_${name})
    add_library(latmpm_${name} INTERFACE)
    target_link_libraries(latmpm_${name} INTERFACE ${library})
    target_include_directories(latmpm_${name} SYSTEM INTERFACE ${include_dir})
    add_library(latmpm::${name} ALIAS latmpm_${name})
  endif()
endfunction()

# gmsh ships no CMake package.
find_library(GMSH_LIBRARY NAMES gmsh REQUIRED)
find_path(GMSH_INCLUDE_DIR NAMES gmsh.h REQUIRED)
latmpm_interface_target(gmsh ${GMSH_LIBRARY} ${GMSH_INCLUDE_DIR})

# SuiteSparse CHOLMOD (libsuitesparse-dev) for the static solver's sparse Cholesky, called
# through its C interface (libs/statics/cholmod_direct), and the explicit solver's null-space
# filter (libs/mpm/null_space_filter, through Eigen's CholmodSupport); Debian's SuiteSparse 5
# ships no CMake package.
find_library(CHOLMOD_LIBRARY NAMES cholmod REQUIRED)
find_path(CHOLMOD_INCLUDE_DIR NAMES cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
latmpm_interface_target(cholmod ${CHOLMOD_LIBRARY} ${CHOLMOD_INCLUDE_DIR})

# hypre (libhypre-dev) for the static solver's AMG-preconditioned CG (libs/statics/hypre_amg);
# an MPI library (OpenMPI, pulled in by libhypre-dev), run as one process. No CMake package.
find_package(MPI REQUIRED COMPONENTS C)
find_library(HYPRE_LIBRARY NAMES HYPRE REQUIRED)
find_path(HYPRE_INCLUDE_DIR NAMES HYPRE.h PATH_SUFFIXES hypre REQUIRED)
latmpm_interface_target(hypre ${HYPRE_LIBRARY} ${HYPRE_INCLUDE_DIR})
target_link_libraries(latmpm_hypre INTERFACE MPI::MPI_C)

if(NOT TARGET latmpm_hdf5)
  add_library(latmpm_hdf5 INTERFACE)
  target_link_libraries(latmpm_hdf5 INTERFACE ${HDF5_C_LIBRARIES})
  target_include_directories(latmpm_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS})
  target_compile_definitions(latmpm_hdf5 INTERFACE ${HDF5_C_DEFINITIONS})
  add_library(latmpm::hdf5 ALIAS latmpm_hdf5)
endif()

if(LATMPM_BUILD_TESTS)
  find_package(Catch2 2 REQUIRED)
  include(Catch)  # catch_discover_tests
endif()
