#!/usr/bin/env bash
# Installs the Debian packages tmop needs that are missing (nothing when all are there).
set -euo pipefail
# gmsh-doc: Gmsh's tutorials and demos, meshed by the tests (recipe_test_meshes.h).
# openssh-client: OpenMPI's mpirun needs an rsh agent on its path even for one machine (the
# MPI tests, tests/parallel/mpi_runs.sh).
pkgs=(build-essential cmake clang libclang-rt-14-dev pkg-config libceres-dev libeigen3-dev libgoogle-glog-dev libgflags-dev
      libopenmesh-dev libgtest-dev libgmock-dev libbenchmark-dev zlib1g-dev gmsh python3 python3-gmsh
      python3-meshio python3-numpy libexodusii-dev python3-netcdf4
      libcgns-dev python3-h5py libmetis-dev python3-vtk9 libopenmpi-dev openmpi-bin
      openssh-client gmsh-doc)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
