#!/usr/bin/env bash
# Sets up and builds GelMPM (contrib/setup.sh), then runs one scene (default: the §4.1 constrained
# swelling benchmark) and says where the results are.
#
#   bash contrib/run.sh [scene.prm] [--set "Section/Entry=value"]...
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "${top}/contrib/setup.sh" --target gelmpm
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
scene="${top}/prm/constrained_swelling.prm"
if [[ $# -gt 0 && "$1" != --* ]]; then scene="$1"; shift; fi
cd "${top}"
exec "${GELMPM_BUILD_DIR:-${top}/build}/gelmpm" "$@" "${scene}"
