#!/usr/bin/env bash
# Installs latmpm's build and run dependencies from Debian packages. Idempotent: does nothing
# when every package is already installed. Uses sudo when not root.
set -euo pipefail
packages=(
  build-essential cmake pkg-config git ccache
  libcgal-dev libeigen3-dev libopenvdb-dev libboost-iostreams-dev libtbb-dev
  libhdf5-dev hdf5-tools libgmsh-dev catch2 gnuplot-nox libtomlplusplus-dev python3
  libsuitesparse-dev libopenblas0-pthread libnlopt-dev
  libhypre-dev
  # The solver on MPI (docs/cluster.md: make mpi, and the mpi.* tests of make test): OpenMPI's
  # headers and mpirun (hypre pulls them in already; named for the tests), and the parallel
  # HDF5 that build writes snapshots and checkpoints with (every process its part of one
  # file). It installs beside the serial libhdf5-dev, which every other build links.
  libopenmpi-dev openmpi-bin libhdf5-openmpi-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done" >&2
