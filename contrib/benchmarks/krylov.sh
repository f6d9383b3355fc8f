#!/usr/bin/env bash
# The iterative solver (Linear solver/Solver = Krylov: GMRES, multigrid on K_uu, a direct solve of
# an approximate mu Schur complement) with both displacement preconditioners, algebraic (AMG:
# smoothed aggregation with the rigid-body modes) and geometric (GMG: the nested B-spline grids),
# against MUMPS:
#   1. Krylov iterations per Newton solve against a fixed dt, from the undrained limit
#      (1e-6 tau_d) to 1e2 tau_d, on §4.1 (prm/constrained_swelling.prm, 3 points per cell) on
#      20 x 160, 40 x 320 and 80 x 640 cells: bounded in dt and in h is the aim;
#   2. wall time and peak memory of AMG, GMG and MUMPS in 3D (prm/free_swelling_cube.prm at 26^3,
#      34^3 and 50^3 cells, dt = 1e-3: at 34^3, dt = 1e-2 takes the solvers into step-size cuts
#      from the second step on);
#   3. the same cubes at the undrained limit (1e-6 tau_d, the boundary's chemical potential
#      jumping within the first step) and at 1e2 tau_d, GMG against MUMPS.
# Every case takes a few steps of a fixed dt (Growth factor 1, no caps, no tolerance) so that
# each solver solves the same systems; the Newton iteration counts must agree. Writes
# <output>/krylov.md (the tables) and, with --update-doc, puts them into doc/performance.md between
# "krylov: begin" and "krylov: end". GELMPM_KRYLOV_CASES (an extended regular expression) runs
# only the cases whose names match (e.g. 'GMG|MUMPS', '^h3d_26'); the others show as "–".
#
#   bash contrib/benchmarks/krylov.sh [--update-doc] [output directory]
#        (default directory: output/krylov)
#
# About 40 minutes on a 2-core machine; run it on an otherwise idle machine.
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "${top}/contrib/benchmarks/doc_driver.sh"
doc_driver_arguments krylov "$@"
echo "krylov.sh: about 40 minutes on a 2-core machine; results in ${out}"

# run_case NAME SCENE SOLVER DT STEPS [--set ...]: STEPS steps of DT with SOLVER (MUMPS, AMG or
# GMG: Krylov with the algebraic or the geometric displacement preconditioner).
run_case() {
  local name="$1" scene="$2" solver="$3" dt="$4" steps="$5"
  shift 5
  [[ -z ${GELMPM_KRYLOV_CASES:-} || ${name} =~ ${GELMPM_KRYLOV_CASES} ]] || return 0
  # A case with a status from an earlier run in the same directory is kept: an interrupted study
  # goes on where it stopped. Use a new directory after changing the solver.
  if [[ -f "${out}/${name}.status" && -f "${out}/${name}.time" ]]; then
    echo "  ${name}: kept from an earlier run"
    return
  fi
  local choice=(--set "Linear solver/Solver=${solver}")
  case "${solver}" in
    AMG) choice=(--set "Linear solver/Solver=Krylov"
                 --set "Linear solver/Displacement preconditioner=algebraic") ;;
    GMG) choice=(--set "Linear solver/Solver=Krylov"
                 --set "Linear solver/Displacement preconditioner=geometric") ;;
  esac
  echo "  ${name}: started $(date +%H:%M:%S)"
  set +e
  /usr/bin/time -f "%e %M" -o "${out}/${name}.time" "${build_dir}/gelmpm" "${top}/prm/${scene}" \
    --set "Output/Directory=${out}/${name}" --set "Output/Write particles=false" \
    "${choice[@]}" --set "Time stepping/Initial step=${dt}" \
    --set "Time stepping/Growth factor=1" --set "Time stepping/Step caps=" \
    --set "Time stepping/Tolerance=0" --set "Time stepping/Stop at times=" \
    --set "Time stepping/End time=$(awk -v d="${dt}" -v n="${steps}" 'BEGIN { print d * n }')" \
    "$@" > "${out}/${name}.log" 2>&1
  echo $? > "${out}/${name}.status"
  set -e
}

# Fields of a case: status, wall s, peak MB, steps, Newton, Krylov per solve, u and mu unknowns
# (last row of statistics.csv); "–" for a case that was not run.
fields() {
  local name="$1" csv="${out}/$1/statistics.csv"
  local status wall memory steps newton per_solve n_u n_mu
  if [[ ! -f "${out}/${name}.status" ]]; then
    echo "–|–|–|–|–|–|–|–"
    return
  fi
  status=$(cat "${out}/${name}.status")
  # /usr/bin/time puts "Command exited with non-zero status N" first for a failed case.
  read -r wall memory < <(tail -n 1 "${out}/${name}.time") || true
  memory=$(awk -v k="${memory:-0}" 'BEGIN { printf "%.0f", k / 1024 }')
  steps=$(grep -o "in [0-9]* steps" "${out}/${name}.log" | awk '{print $2; exit}')
  newton=$(grep -o "[0-9]* Newton iterations," "${out}/${name}.log" | awk '{print $1; exit}')
  per_solve=$(grep -o "([0-9.e+-]* per solve)" "${out}/${name}.log" | tr -d '(' | awk '{printf "%.1f", $1; exit}')
  n_u=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "n_dofs_u") c = i } NR > 1 { v = $c } END { print v }' "${csv}" 2> /dev/null)
  n_mu=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "n_dofs_mu") c = i } NR > 1 { v = $c } END { print v }' "${csv}" 2> /dev/null)
  [[ ${status} == 0 ]] || per_solve="failed (exit ${status})"
  echo "${status}|${wall}|${memory}|${steps:-–}|${newton:-–}|${per_solve:-–}|${n_u:-–}|${n_mu:-–}"
}

# row LABEL CELLS RUN: one table row from RUN_AMG, RUN_GMG and RUN_MUMPS.
row() {
  local sa wa ma sta na pa ua mua sg wg mg stg ng pg ug mug sm wm mm stm nm pm um mum
  IFS='|' read -r sa wa ma sta na pa ua mua <<< "$(fields "$3_AMG")"
  IFS='|' read -r sg wg mg stg ng pg ug mug <<< "$(fields "$3_GMG")"
  IFS='|' read -r sm wm mm stm nm pm um mum <<< "$(fields "$3_MUMPS")"
  local u="${um}" mu="${mum}"
  [[ ${u} != – ]] || { u="${ug}"; mu="${mug}"; }
  [[ ${u} != – ]] || { u="${ua}"; mu="${mua}"; }
  echo "| $1 | $2 | ${u} + ${mu} | ${pa} | ${pg} | ${na} / ${ng} / ${nm} | ${wa} / ${wg} / ${wm} | ${ma} / ${mg} / ${mm} |"
}

swelling=constrained_swelling.prm
cube=free_swelling_cube.prm

# 1. dt and h, 2D.
dts=(1e-6 1e-4 1e-2 1 1e2)
grids=("20, 160" "40, 320" "80, 640")
for grid in "${grids[@]}"; do
  for dt in "${dts[@]}"; do
    for solver in AMG GMG MUMPS; do
      run_case "h2d_${grid//, /x}_${dt}_${solver}" "${swelling}" "${solver}" "${dt}" 3 \
        --set "Background grid/Cells=${grid}" --set "Material points/Points per cell=3"
    done
  done
done
# 2. 3D.
cubes=(26 34 50)
for n in "${cubes[@]}"; do
  for solver in AMG GMG MUMPS; do
    run_case "h3d_${n}_${solver}" "${cube}" "${solver}" 1e-3 2 --set "Background grid/Cells=${n}, ${n}, ${n}"
  done
done

# 3. 3D at the two limits of dt, with the geometric preconditioner (the default) and MUMPS: the
# undrained limit needs a load that is not ramped over the step, so there the boundary's chemical
# potential jumps within the first step (tinc = dt); at 1e2 tau_d the first step takes the whole
# ramp (tinc = 1). A solve that does not converge in 200 iterations fails the Newton iteration, and
# a step cut below dt / 5 ends the case (it failed), so that a preconditioner that stalls costs
# minutes, not hours.
dts3d=(1e-6 1e2)
for n in "${cubes[@]}"; do
  for dt in "${dts3d[@]}"; do
    tinc=1
    [[ ${dt} != 1e-6 ]] || tinc=1e-6
    for solver in GMG MUMPS; do
      run_case "h3d_${n}_${dt}_${solver}" "${cube}" "${solver}" "${dt}" 2 \
        --set "Background grid/Cells=${n}, ${n}, ${n}" --set "Linear solver/Krylov iterations=200" \
        --set "Time stepping/Minimum step=$(awk -v d="${dt}" 'BEGIN { print d / 5 }')" \
        --set "Boundary conditions/right/Chemical potential value/Function constants=mu0=-0.14597453, tinc=${tinc}" \
        --set "Boundary conditions/outer/Chemical potential value/Function constants=mu0=-0.14597453, tinc=${tinc}"
    done
  done
done

header="| dt / tau_d | cells | u + mu unknowns | Krylov per solve, AMG | Krylov per solve, GMG | Newton (AMG / GMG / MUMPS) | wall s (AMG / GMG / MUMPS) | memory MB (AMG / GMG / MUMPS) |"
{
  echo "Krylov iterations per Newton solve with the algebraic (AMG) and the geometric (GMG)"
  echo "displacement preconditioner, against dt and h (§4.1 with 3 points per cell, 3 steps of dt"
  echo "from the initial state; relative residual reduction 1e-8 per solve). Wall time of the whole run"
  echo "(set-up, assembly and output included), peak resident memory of the process:"
  echo
  echo "${header}"
  echo "|---|---|---|---|---|---|---|---|"
  for grid in "${grids[@]}"; do
    for dt in "${dts[@]}"; do
      row "${dt}" "${grid//, /x}" "h2d_${grid//, /x}_${dt}"
    done
  done
  echo
  echo "3D: the free-swelling cube (prm/free_swelling_cube.prm), 2 steps of dt = 1e-3 tau_d:"
  echo
  echo "${header/dt \/ tau_d/case}"
  echo "|---|---|---|---|---|---|---|---|"
  for n in "${cubes[@]}"; do
    row "3D cube" "${n}^3" "h3d_${n}"
  done
  echo
  echo "3D at the limits of dt: the cube, 2 steps; at 1e-6 tau_d the boundary's chemical potential"
  echo "jumps within the first step (the undrained limit), at 1e2 tau_d the first step takes the"
  echo "whole ramp (AMG not run):"
  echo
  echo "${header}"
  echo "|---|---|---|---|---|---|---|---|"
  for n in "${cubes[@]}"; do
    for dt in "${dts3d[@]}"; do
      row "${dt}" "${n}^3" "h3d_${n}_${dt}"
    done
  done
  echo
  echo "Produced by \`bash contrib/benchmarks/krylov.sh\` on $(nproc) cores, $(date +%Y-%m-%d)${GELMPM_KRYLOV_CASES:+ (cases matching '${GELMPM_KRYLOV_CASES}')}."
} > "${out}/krylov.md"
cat "${out}/krylov.md"

if [[ ${update_doc} == 1 ]]; then
  write_between_markers "${top}/doc/performance.md" krylov "${out}/krylov.md"
fi
