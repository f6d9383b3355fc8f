#!/usr/bin/env bash
# Sets up GelMPM on Debian 12: installs the Debian packages that are missing, configures and builds
# into build/ (Release). Idempotent: a second call only rebuilds what changed.
#
#   bash contrib/setup.sh [--plotting] [--target <target>]...
#
# --target builds the targets named and what they need instead of everything (contrib/run.sh
# builds only gelmpm, not the peer and reference tools that the tests use; contrib/test.sh builds
# everything and the test programs, target test_programs, in one build).
# --plotting also installs what the plotting scripts in contrib/plotting need (matplotlib, numpy;
# they read .vtu files with VTK's Python module, as the tests do); run those scripts with
# /usr/bin/python3, which sees Debian's packages.
# Environment: GELMPM_BUILD_DIR (default: build), GELMPM_BUILD_TYPE (default: Release), GELMPM_JOBS.
#
# ParaView: the tests read the written .vtu files with VTK's XML reader, the one ParaView uses,
# through Python's vtkmodules (tests/vtu_reader.h). Debian has two packages that provide it and
# conflict with each other: python3-vtk9 (VTK's) and python3-paraview (ParaView's, which
# 'apt-get install paraview' brings). So python3-vtk9 is installed only when /usr/bin/python3
# cannot import vtkmodules.vtkIOXML: a machine with ParaView keeps ParaView's, and ParaView can be
# installed after GelMPM (apt then replaces python3-vtk9 by python3-paraview, and the tests read
# with that). VTK's C++ development package (libvtk9-dev) is not needed: it depends on
# python3-vtk9, so it cannot be installed beside ParaView's Python, and it brings a JDK, GDAL and
# MySQL's development files: 279 packages and 994 MB installed beyond what the packages above
# bring, against 55 and 245 MB for python3-vtk9 (apt's resolution from an empty system).
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${GELMPM_BUILD_DIR:-${top}/build}"
build_type="${GELMPM_BUILD_TYPE:-Release}"
jobs="${GELMPM_JOBS:-$(nproc)}"

# Each package and why GelMPM needs it (README.md, "Dependencies", points here):
packages=(
  libdeal.ii-dev # deal.II 9.4 with Trilinos (Amesos, Epetra), MUMPS, ARPACK, Boost, TBB, MPI
  libmuparser-dev # boundary selectors in x, y, z, nx, ny, nz (the parser behind deal.II's)
  libopenblas0-pthread # optimised BLAS behind MUMPS and LAPACK (replaces the reference BLAS)
  numdiff        # ctest compares outputs with tolerances
  cmake          # build system
  g++            # compiler
  make           # build tool
  ninja-build    # builds a fresh build directory (better use of two cores than make)
)
targets=()
while (($#)); do
  case "$1" in
    --plotting) packages+=(python3-numpy python3-matplotlib) ;;
    --target)
      [[ $# -ge 2 ]] || { echo "error: --target needs a target name, e.g. --target gelmpm" >&2; exit 1; }
      targets+=("$2")
      shift ;;
    *) echo "error: unknown option '$1' (usage: contrib/setup.sh [--plotting] [--target <target>]...)" >&2
       exit 1 ;;
  esac
  shift
done

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

# VTK's Python module, for the tests that read .vtu files (and the plotting scripts): whichever of
# python3-vtk9 and python3-paraview is there; python3-vtk9 if neither.
if /usr/bin/python3 -c "import vtkmodules.vtkIOXML" >/dev/null 2>&1; then
  echo "GelMPM setup: VTK's Python module found (python3-vtk9 or ParaView's python3-paraview):" \
       "the tests read .vtu files with it"
else
  missing+=(python3-vtk9)
  echo "GelMPM setup: /usr/bin/python3 cannot import vtkmodules.vtkIOXML: installing python3-vtk9," \
       "with which the tests read .vtu files as ParaView does (ParaView's python3-paraview, if" \
       "installed later, replaces it and serves as well)"
fi

if ((${#missing[@]})); then
  echo "GelMPM setup: installing missing Debian packages: ${missing[*]} (why: contrib/setup.sh, top)"
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

# A fresh build directory is built by Ninja, which schedules the whole build as one graph, where
# make starts a target's files only once the targets it links are built (doc/architecture.md,
# "Build time": 297 s of wall time on two cores with Ninja, 345 s with make, measured together
# with the tools made one program). An existing build directory keeps the generator it was configured with.
# (make if ninja is not there, e.g. where the packages were installed by hand).
if [[ ! -f "${build_dir}/CMakeCache.txt" ]]; then
  generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  cmake -S "${top}" -B "${build_dir}" "${generator[@]}" -DCMAKE_BUILD_TYPE="${build_type}" >/dev/null
elif ((${#targets[@]})); then
  # Configured anew first: make reads its targets before it would reconfigure, so a target that
  # a changed CMakeLists.txt adds (test_programs) would be unknown to it.
  cmake -S "${top}" -B "${build_dir}" >/dev/null
fi
if ((${#targets[@]})); then
  cmake --build "${build_dir}" -j "${jobs}" --target "${targets[@]}"
else
  cmake --build "${build_dir}" -j "${jobs}"
fi
