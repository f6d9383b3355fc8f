#!/usr/bin/env bash
# The onset of swell-induced buckling of the §4.3 column (prm/column_buckling.prm) with the
# body-fitted FE peer (gelmpm-fem-column: Taylor-Hood Q2-Q1 on n x 8n cells) under mesh
# refinement: steps capped at 0.02 tau_d, the loss of stability bracketed to 1e-3 tau_d by the
# signature of the tangent, run to 0.4 tau_d (paper: t_onset = 0.28 tau_d; doc/fem_peer.md).
#
#   bash contrib/benchmarks/column_onset_fem.sh [results directory (default:
#        output/column_onset_fem)] [n ...]
#
# Writes <dir>/column_onset_fem.csv (cells, unknowns, t_stable, t_unstable, wall_seconds; an
# empty bracket if none was found) and one log per mesh. Set GELMPM_BUILD_DIR to the build
# directory holding gelmpm-fem-column (default: build/).
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
tool="${GELMPM_BUILD_DIR:-${top}/build}/gelmpm-fem-column"
dir="${1:-output/column_onset_fem}"
shift || true
levels=("$@")
((${#levels[@]})) || levels=(2 4 8 16)
if [[ ! -x "${tool}" ]]; then
  echo "no ${tool}: build it first (cmake --build build --target gelmpm-tools)" >&2
  exit 2
fi
# Measured on the 2-core machine with other jobs running: 2, 4, 8, 16, 32 cells across took
# about 3, 4, 22, 143 and (to the bracket only) 1155 s; idle, 8 cells take about 9 s.
declare -A estimate=([1]=2 [2]=3 [4]=4 [8]=22 [16]=143 [32]=1800)
total=0
for n in "${levels[@]}"; do total=$((total + ${estimate[${n}]:-$((n * n / 4))})); done
echo "column onset with the FE peer, n = ${levels[*]}: about ${total} s on a 2-core machine"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "${dir}"
csv="${dir}/column_onset_fem.csv"
echo "cells,unknowns,t_stable,t_unstable,wall_seconds" > "${csv}"
for n in "${levels[@]}"; do
  log="${dir}/cells-${n}.log"
  start=$(date +%s.%N)
  # The scene's gel and Newton; steps of 0.02 tau_d, the tangent's signature brackets the onset.
  if ! "${tool}" "${top}/prm/column_buckling.prm" --set "FE peer/Cells=${n}" \
    --set "Time stepping/End time=0.4" --set "Time stepping/Initial step=0.02" \
    --set "Time stepping/Step caps=0.4: 0.02" --set "Time stepping/Stop at times=" \
    --set "Time stepping/Tolerance=0" --set "Stability/Onset criterion=tangent" \
    --set "Stability/Bisection tolerance=1e-3" > "${log}" 2>&1; then
    echo "n = ${n}: the run failed, see ${log} (not in the table)"
    continue
  fi
  seconds=$(echo "$(date +%s.%N) - ${start}" | bc)
  unknowns=$(sed -n 's/.* cells, Q[0-9]*-Q[0-9]*, \([0-9]*\) DoFs.*/\1/p' "${log}")
  # The first bracket (the run reports each on its own line).
  bracket=$(sed -n 's/.*loss of stability between t\/tau_d = \([0-9.e+-]*\) and \([0-9.e+-]*\)/\1,\2/p' \
    "${log}" | head -n 1)
  [[ -n "${bracket}" ]] || bracket=","
  echo "${n},${unknowns},${bracket},${seconds}" >> "${csv}"
  printf 'n = %3d  %7d unknowns  onset bracket %-24s (%.1f s)\n' "${n}" "${unknowns}" \
    "${bracket/,/ - }" "${seconds}"
done
echo "results: ${csv}"
