# The MPI solver for the mpi.* tests of a build without -DLATMPM_MPI=ON: a second build of
# this source tree in <build>/mpi/ with LATMPM_MPI=ON and only the latmpm-solve target, so
# `make test` runs the solver on 2, 3 and 4 processes while the plain build (and every other
# test) stays the one-process solver that users without MPI get. MPI itself is found by every
# build (hypre, cmake/LatmpmDependencies.cmake); mpiexec comes with it (libhypre-dev ->
# mpi-default-dev -> libopenmpi-dev -> openmpi-bin). Off: -DLATMPM_MPI_TESTS=OFF (the mpi.*
# tests then report skipped).
#
# latmpm_mpi_solver(<out_var>): sets <out_var> to the MPI latmpm-solve's path, or "" when
# there is none (no mpiexec, or the option off).
include(ExternalProject)
option(LATMPM_MPI_TESTS "Build the MPI solver beside a plain build so make test runs the mpi.* tests" ON)

function(latmpm_mpi_solver out_var)
  if(LATMPM_MPI)
    set(${out_var} $<TARGET_FILE:latmpm-solve> PARENT_SCOPE)
    return()
  endif()
  if(NOT LATMPM_MPI_TESTS OR NOT MPIEXEC_EXECUTABLE)
    set(${out_var} "" PARENT_SCOPE)
    return()
  endif()
  set(dir ${PROJECT_BINARY_DIR}/mpi)
  # Under make, the inner build shares the outer one's job slots (-jN): $(MAKE) is make's
  # recursive call. Other generators build with every core.
  if(CMAKE_GENERATOR MATCHES "Make")
    set(build $(MAKE) latmpm-solve)
  else()
    set(build ${CMAKE_COMMAND} --build ${dir} --target latmpm-solve --parallel)
  endif()
  ExternalProject_Add(latmpm_mpi_solver
    SOURCE_DIR ${PROJECT_SOURCE_DIR}
    BINARY_DIR ${dir}
    CMAKE_ARGS -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
               -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
               -DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}
               -DLATMPM_MPI=ON -DLATMPM_BUILD_TESTS=OFF -DLATMPM_BUILD_BENCH=OFF
               -DLATMPM_NATIVE=${LATMPM_NATIVE} -DLATMPM_PRECISION=${LATMPM_PRECISION}
    BUILD_COMMAND ${build}
    BUILD_ALWAYS ON  # the sources are this tree's: let the inner build decide what changed
    # Not part of `all`: a plain make / make demo compiles the solver once, and a broken MPI
    # install cannot fail it; ctest builds this first (tests/mpi, fixture mpi_solver).
    EXCLUDE_FROM_ALL TRUE
    INSTALL_COMMAND ""
    BUILD_BYPRODUCTS ${dir}/bin/latmpm-solve)
  set(${out_var} ${dir}/bin/latmpm-solve PARENT_SCOPE)
endfunction()
