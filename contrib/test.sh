#!/usr/bin/env bash
# Sets up and builds GelMPM (contrib/setup.sh), then runs the whole ctest suite.
#
#   bash contrib/test.sh [extra ctest arguments]
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "${top}/contrib/setup.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "${GELMPM_BUILD_DIR:-${top}/build}"
ctest -j "${GELMPM_JOBS:-$(nproc)}" --output-on-failure "$@"
