#!/usr/bin/env bash
# Sets up GelMPM on Debian 12: installs the Debian packages that are missing, configures and builds
# into build/ (Release). Idempotent: a second call only rebuilds what changed.
#
#   bash contrib/setup.sh [--plotting]
#
# --plotting also installs what the plotting scripts in contrib/plotting need (matplotlib, numpy,
# VTK's Python module); run those scripts with /usr/bin/python3, which sees Debian's packages.
# Environment: GELMPM_BUILD_DIR (default: build), GELMPM_BUILD_TYPE (default: Release), GELMPM_JOBS.
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${GELMPM_BUILD_DIR:-${top}/build}"
build_type="${GELMPM_BUILD_TYPE:-Release}"
jobs="${GELMPM_JOBS:-$(nproc)}"

# Each package and why GelMPM needs it (README.md, "Dependencies", points here):
packages=(
  libdeal.ii-dev # deal.II 9.4 with Trilinos (Amesos, Epetra), MUMPS, ARPACK, Boost, TBB, MPI
  libmuparser-dev # boundary selectors in x, y, z, nx, ny, nz (the parser behind deal.II's)
  libvtk9-dev    # tests read written .vtu files back the way ParaView does
  libopenblas0-pthread # optimised BLAS behind MUMPS and LAPACK (replaces the reference BLAS)
  numdiff        # ctest compares outputs with tolerances
  cmake          # build system
  g++            # compiler
  make           # build tool
)
if [[ "${1:-}" == "--plotting" ]]; then
  packages+=(python3-numpy python3-matplotlib python3-vtk9)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  echo "GelMPM setup: installing missing Debian packages: ${missing[*]}"
  sudo=""
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "error: need root or sudo to install ${missing[*]}" >&2; exit 1; }
    sudo="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Open MPI refuses to start as root unless told; CI runs as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

if [[ ! -f "${build_dir}/CMakeCache.txt" ]]; then
  cmake -S "${top}" -B "${build_dir}" -DCMAKE_BUILD_TYPE="${build_type}" >/dev/null
fi
cmake --build "${build_dir}" -j "${jobs}"
