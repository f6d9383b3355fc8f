#!/usr/bin/env bash
# The discrete inf-sup constant beta_h of the undrained u-mu problem for Q2-Q2, Q3-Q2 and Q2-Q2SD
# on a refining sequence of grids (doc/inf_sup.md). The body is the H x H gel of prm/flat_punch.prm
# with a free, impermeable top and rollers elsewhere, at its initial state; the grid has n x n cells
# over 1.5H x 1.5H (h = 1.5H/n, the body aligned with the grid), 3 x 3 points per cell.
#
#   bash contrib/benchmarks/inf_sup.sh [results directory (default: output/inf_sup_study)] [n ...]
#
# Writes <dir>/inf_sup.csv (pair, cells, h, n_dofs_u, n_dofs_mu, beta_h, wall seconds) and, with
# python3-matplotlib (bash contrib/setup.sh --plotting), <dir>/inf_sup.png. About 2 minutes with
# the default levels 12 24 48 72 on a 2-core machine (the dense eigenproblem dominates at n = 72).
set -euo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
gelmpm="${GELMPM_BUILD_DIR:-${top}/build}/gelmpm"
dir="${1:-output/inf_sup_study}"
shift || true
levels=("$@")
((${#levels[@]})) || levels=(12 24 48 72)
[[ -x "${gelmpm}" ]] || bash "${top}/contrib/setup.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "${dir}"
csv="${dir}/inf_sup.csv"
echo "pair,cells,h,n_dofs_u,n_dofs_mu,beta_h,wall_seconds" > "${csv}"
for pair in Q2-Q2 Q3-Q2 Q2-Q2SD; do
  case ${pair} in
    Q2-Q2) options=(--set "Discretisation/Chemical potential grid=same") ;;
    Q3-Q2) options=(--set "Discretisation/Chemical potential grid=same"
                    --set "Discretisation/Displacement degree=3") ;;
    Q2-Q2SD) options=() ;;
  esac
  for n in "${levels[@]}"; do
    run="${dir}/${pair}-${n}"
    start=$(date +%s.%N)
    if ! "${gelmpm}" --set "Output/Directory=${run}" --set "Output/Write particles=false" \
      --set "Background grid/Cells=${n}, ${n}" --set "Material points/Points per cell=3" \
      --set "Boundary conditions/punch/Displacement=free" \
      --set "Time stepping/End time=3.125e-7" --set "Stability/Inf-sup constant=true" \
      "${options[@]}" "${top}/prm/flat_punch.prm" > "${run}.log" 2>&1; then
      echo "${pair} n = ${n}: the run failed, see ${run}.log (not in the table)"
      continue
    fi
    seconds=$(echo "$(date +%s.%N) - ${start}" | bc)
    row=$(python3 - "${run}/statistics.csv" <<'PY'
import csv, sys
last = list(csv.DictReader(open(sys.argv[1])))[-1]
print(f"{last['n_dofs_u']},{last['n_dofs_mu']},{last['inf_sup']}")
PY
)
    h=$(echo "scale=6; 1.5 / ${n}" | bc)
    echo "${pair},${n},${h},${row},${seconds}" >> "${csv}"
    printf '%-8s n = %3d  h = %s H  beta_h = %s  (%.1f s)\n' "${pair}" "${n}" "${h}" \
      "${row##*,}" "${seconds}"
  done
done
echo "results: ${csv}"
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 "${top}/contrib/plotting/inf_sup.py" "${csv}" "${dir}/inf_sup.png"
  echo "plot: ${dir}/inf_sup.png"
fi
