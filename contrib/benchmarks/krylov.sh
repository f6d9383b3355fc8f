#!/usr/bin/env bash
# The iterative solver (Linear solver/Solver = Krylov: GMRES, AMG on K_uu with the rigid-body
# modes, a direct solve of an approximate mu Schur complement) against MUMPS:
#   1. Krylov iterations per Newton solve against a fixed dt, from the undrained limit
#      (1e-6 tau_d) to 1e2 tau_d, on §4.1 (prm/constrained_swelling.prm) on 20 x 160 cells (its
#      2,000 or fewer displacement unknowns are the AMG's coarse level: A is solved exactly, and
#      the counts measure the Schur approximation alone) and on 40 x 320 (two AMG levels);
#   2. against h: §4.1 on 20 x 160, 40 x 320 and 80 x 640 cells (3 points per cell), dt = 1e-2;
#   3. wall time and peak memory of Krylov and MUMPS on the same steps, in 2D (the grids of 2)
#      and 3D (prm/free_swelling_cube.prm at 26^3, 34^3 and 50^3 cells, dt = 1e-3: at 34^3, dt = 1e-2
#      takes both solvers into step-size cuts from the second step on).
# Every case takes a few steps of a fixed dt (Growth factor 1, no caps, no tolerance) so that
# each solver solves the same systems; the Newton iteration counts of the two must agree, and
# the script says where they do not. Writes <output>/krylov.md (the tables) and, with
# --update-doc, puts them into doc/performance.md between "krylov: begin" and "krylov: end".
#
#   bash contrib/benchmarks/krylov.sh [--update-doc] [output directory]
#        (default directory: output/krylov)
#
# About 25 minutes on a 2-core machine; run it on an otherwise idle machine.
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "${top}/contrib/benchmarks/doc_driver.sh"
doc_driver_arguments krylov "$@"
echo "krylov.sh: about 25 minutes on a 2-core machine; results in ${out}"

# run_case NAME SCENE SOLVER DT STEPS [--set ...]: STEPS steps of DT with SOLVER.
run_case() {
  local name="$1" scene="$2" solver="$3" dt="$4" steps="$5"
  shift 5
  # A case with a status from an earlier run in the same directory is kept: an interrupted study
  # goes on where it stopped. Use a new directory after changing the solver.
  if [[ -f "${out}/${name}.status" && -f "${out}/${name}.time" ]]; then
    echo "  ${name}: kept from an earlier run"
    return
  fi
  echo "  ${name}: started $(date +%H:%M:%S)"
  set +e
  /usr/bin/time -f "%e %M" -o "${out}/${name}.time" "${build_dir}/gelmpm" "${top}/prm/${scene}" \
    --set "Output/Directory=${out}/${name}" --set "Output/Write particles=false" \
    --set "Linear solver/Solver=${solver}" --set "Time stepping/Initial step=${dt}" \
    --set "Time stepping/Growth factor=1" --set "Time stepping/Step caps=" \
    --set "Time stepping/Tolerance=0" --set "Time stepping/Stop at times=" \
    --set "Time stepping/End time=$(awk -v d="${dt}" -v n="${steps}" 'BEGIN { print d * n }')" \
    "$@" > "${out}/${name}.log" 2>&1
  echo $? > "${out}/${name}.status"
  set -e
}

# Fields of a case: status, wall s, peak MB, steps, Newton, Krylov per solve, most in a step,
# u and mu unknowns (last row of statistics.csv).
fields() {
  local name="$1" csv="${out}/$1/statistics.csv"
  local status wall memory steps newton per_solve n_u n_mu
  status=$(cat "${out}/${name}.status")
  read -r wall memory < "${out}/${name}.time" || true
  memory=$(awk -v k="${memory:-0}" 'BEGIN { printf "%.0f", k / 1024 }')
  steps=$(grep -o "in [0-9]* steps" "${out}/${name}.log" | awk '{print $2; exit}')
  newton=$(grep -o "[0-9]* Newton iterations," "${out}/${name}.log" | awk '{print $1; exit}')
  per_solve=$(grep -o "([0-9.e+-]* per solve)" "${out}/${name}.log" | tr -d '(' | awk '{printf "%.1f", $1; exit}')
  n_u=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "n_dofs_u") c = i } NR > 1 { v = $c } END { print v }' "${csv}" 2> /dev/null)
  n_mu=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "n_dofs_mu") c = i } NR > 1 { v = $c } END { print v }' "${csv}" 2> /dev/null)
  echo "${status}|${wall}|${memory}|${steps:-–}|${newton:-–}|${per_solve:-–}|${n_u:-–}|${n_mu:-–}"
}

# comparison_row CASE CELLS RUN: one row of the second table from RUN_Krylov and RUN_MUMPS.
comparison_row() {
  local sk wk mk stk nk pk uk muk sm wm mm stm nm pm um mum
  IFS='|' read -r sk wk mk stk nk pk uk muk <<< "$(fields "$3_Krylov")"
  IFS='|' read -r sm wm mm stm nm pm um mum <<< "$(fields "$3_MUMPS")"
  [[ ${sk} == 0 ]] || pk="failed (exit ${sk})"
  [[ ${sm} == 0 ]] || wm="failed (exit ${sm})"
  echo "| $1 | $2 | ${um} + ${mum} | ${pk} | ${nk} / ${nm} | ${wk} | ${wm} | ${mk} | ${mm} |"
}

swelling=constrained_swelling.prm
cube=free_swelling_cube.prm

# 1. dt.
dts=(1e-6 1e-4 1e-2 1 1e2)
fine=(--set "Background grid/Cells=40, 320" --set "Material points/Points per cell=3")
for dt in "${dts[@]}"; do
  run_case "dt_${dt}_Krylov" "${swelling}" Krylov "${dt}" 3
  run_case "dt_${dt}_MUMPS" "${swelling}" MUMPS "${dt}" 3
  run_case "dtfine_${dt}_Krylov" "${swelling}" Krylov "${dt}" 3 "${fine[@]}"
  run_case "dtfine_${dt}_MUMPS" "${swelling}" MUMPS "${dt}" 3 "${fine[@]}"
done
# 2. and 3. h, 2D.
grids=("20, 160" "40, 320" "80, 640")
for grid in "${grids[@]}"; do
  tag="${grid//, /x}"
  for solver in Krylov MUMPS; do
    run_case "h2d_${tag}_${solver}" "${swelling}" "${solver}" 1e-2 3 \
      --set "Background grid/Cells=${grid}" --set "Material points/Points per cell=3"
  done
done
# 3. 3D.
cubes=(26 34 50)
for n in "${cubes[@]}"; do
  for solver in Krylov MUMPS; do
    run_case "h3d_${n}_${solver}" "${cube}" "${solver}" 1e-3 2 --set "Background grid/Cells=${n}, ${n}, ${n}"
  done
done

{
  echo "Krylov iterations per Newton solve against a fixed dt (§4.1, 3 steps of dt from the initial"
  echo "state; relative residual reduction 1e-8 per solve; 20 x 160 cells with 6 points per cell, 40 x"
  echo "320 with 3):"
  echo
  echo "| dt / tau_d | cells | u + mu unknowns | Newton iterations (Krylov / MUMPS) | Krylov iterations per solve | wall s (Krylov / MUMPS) |"
  echo "|---|---|---|---|---|---|"
  for prefix in dt dtfine; do
    for dt in "${dts[@]}"; do
      IFS='|' read -r sk wk mk stk nk pk uk muk <<< "$(fields "${prefix}_${dt}_Krylov")"
      IFS='|' read -r sm wm mm stm nm pm um mum <<< "$(fields "${prefix}_${dt}_MUMPS")"
      [[ ${sk} == 0 ]] || pk="failed (exit ${sk})"
      cells="20 x 160"
      [[ ${prefix} == dt ]] || cells="40 x 320"
      echo "| ${dt} | ${cells} | ${uk} + ${muk} | ${nk} / ${nm} | ${pk} | ${wk} / ${wm} |"
    done
  done
  echo
  echo "Against h and against MUMPS (2D: §4.1 with 3 points per cell, 3 steps of dt = 1e-2 tau_d;"
  echo "3D: the free-swelling cube, prm/free_swelling_cube.prm, 2 steps of 1e-3). Wall time of the whole run"
  echo "(set-up, assembly and output included), peak resident memory of the process:"
  echo
  echo "| case | cells | u + mu unknowns | Krylov iterations per solve | Newton (Krylov / MUMPS) | wall s Krylov | wall s MUMPS | memory MB Krylov | memory MB MUMPS |"
  echo "|---|---|---|---|---|---|---|---|---|"
  for grid in "${grids[@]}"; do
    comparison_row "2D §4.1" "${grid//, /x}" "h2d_${grid//, /x}"
  done
  for n in "${cubes[@]}"; do
    comparison_row "3D cube" "${n}^3" "h3d_${n}"
  done
  echo
  echo "Produced by \`bash contrib/benchmarks/krylov.sh\` on $(nproc) cores, $(date +%Y-%m-%d)."
} > "${out}/krylov.md"
cat "${out}/krylov.md"

if [[ ${update_doc} == 1 ]]; then
  write_between_markers "${top}/doc/performance.md" krylov "${out}/krylov.md"
fi
