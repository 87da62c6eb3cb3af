#!/usr/bin/env bash
# Installs every Debian 12 package softgrasp needs to build, test and run.
# Idempotent: when everything is already present it only checks and exits.
# Usage: scripts/install-dependencies.sh   (as root, or with sudo available)
set -euo pipefail

packages=(
  # build tools
  build-essential cmake ninja-build ccache pkg-config clang-format
  # a fast linker (cmake/build_speed.cmake picks it up)
  mold
  # finite elements (deal.II 9.4 with Trilinos, MPI, p4est, HDF5, ADOL-C)
  libdeal.ii-dev
  # MPI runtime for mpirun
  openmpi-bin libopenmpi-dev
  # rigid environment: MuJoCo 2.2 and what its CMake config needs
  libmujoco-dev libqhull-dev libgl-dev
  # data, algebra, serialization
  libhdf5-dev libeigen3-dev libboost-dev libboost-serialization-dev
  # optimised BLAS/LAPACK for the direct solver (MUMPS): becomes the system's
  # libblas.so.3 and liblapack.so.3 through Debian's alternatives
  libopenblas0-serial
  # testing and plotting
  numdiff libbenchmark-dev gnuplot-nox time
  # the independent reference code of benchmarks/calculix (not needed to
  # build or test)
  calculix-ccx
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "softgrasp: all ${#packages[@]} required packages are installed."
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "softgrasp: need root (or sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
fi

echo "softgrasp: installing ${#missing[@]} missing package(s): ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "softgrasp: dependencies installed."
