#!/usr/bin/env bash
# Sets up and builds GelMPM (contrib/setup.sh), then runs the whole ctest suite.
#
#   bash contrib/test.sh [extra ctest arguments]
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# The test programs in the same build as the rest: one graph keeps both cores busy (ctest's
# test_programs.build then finds them built).
bash "${top}/contrib/setup.sh" --target all --target test_programs
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "${GELMPM_BUILD_DIR:-${top}/build}"
ctest -j "${GELMPM_JOBS:-$(nproc)}" --output-on-failure "$@"
