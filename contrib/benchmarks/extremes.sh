#!/usr/bin/env bash
# The tables of doc/extremes.md (numerical stability at the extremes), every case with the command
# lines given there:
#   undrained limit  the flat punch (prm/flat_punch.prm, 30 x 30 cells, 3 x 3 points per cell)
#                    ramped over 10 steps of dt = 1e-4, 1e-6, 1e-8, 1e-10 tau_d, Q2-Q2SD and Q2-Q2
#                    (Chemical potential grid = same), with the inertia and mu_oscillation on;
#   Nitsche          §4.1 (prm/constrained_swelling.prm, u on 20 x 60 cells of 0.5 x 1.5, 3 x 3
#                    points per cell) to t = 0.1 tau_d with the inertia, the condition number and
#                    the boundary condition errors on: symmetric, gamma_u = 1 ... 1e6 at
#                    gamma_mu = 25, and gamma_mu = 0.01 ... 1e6 at gamma_u = 1000 (Table 1, run
#                    once for both tables); skew-symmetric without the stability analysis (its
#                    tangent is not symmetric), gamma_u = 1, 10, 100, 1000 at gamma_mu = 25 and
#                    gamma_mu = 0.1, 1 at gamma_u = 1000.
# A run that cannot converge (exit status 1) is a row of its table, "stopped" at the time reached.
#
#   bash contrib/benchmarks/extremes.sh [output directory]   (default: output/extremes_study)
#
# Writes into the directory: <run>/ (statistics.csv, parameters.prm; particles are not written),
# <run>.log (gelmpm's stdout and stderr), runs.csv (run, exit status, wall seconds, 1-minute load
# average at the start of the run) and extremes.md (the tables in the columns of doc/extremes.md,
# and the figures the prose there quotes), made by contrib/benchmarks/extremes_tables.py, which
# can also be run alone on a directory of finished runs. About 2 minutes on a 2-core machine.
# Exit status: 0 if every run ended with status 0 or 1 and the tables were written, else 2 (a
# run failed otherwise: a crash, an input error) or the table script's.
# Needs the build (bash contrib/setup.sh) and /usr/bin/python3.
# Environment: GELMPM_BUILD_DIR (default: build).
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${GELMPM_BUILD_DIR:-${top}/build}"
out=""
for argument in "$@"; do
  case "${argument}" in
    -h | --help) sed -n '2,26p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "error: unknown option ${argument} (see --help)" >&2; exit 2 ;;
    *) out="${argument}" ;;
  esac
done
out="${out:-${top}/output/extremes_study}"
mkdir -p "${out}"
out="$(cd "${out}" && pwd)"
# Open MPI refuses root unless told twice (containers).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

[[ -x "${build_dir}/gelmpm" ]] || { echo "error: ${build_dir}/gelmpm missing; run bash contrib/setup.sh" >&2; exit 2; }

seconds() { date +%s.%N; }
difference() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }

echo "extremes.sh: the runs of doc/extremes.md into ${out}"
echo "  binary: ${build_dir}/gelmpm"
echo "run,exit_status,wall_seconds,load_average" >"${out}/runs.csv"
status=0
start=$(seconds)

# run_case NAME SCENE [gelmpm arguments...]: gelmpm on prm/SCENE into ${out}/NAME.
run_case() {
  local name="$1" scene="$2"
  shift 2
  local load run_start run_status wall
  load=$(cut -d ' ' -f 1 /proc/loadavg)
  rm -rf "${out:?}/${name}"
  run_start=$(seconds)
  run_status=0
  "${build_dir}/gelmpm" --set "Output/Directory=${out}/${name}" --set "Output/Write particles=false" \
    "$@" "${top}/prm/${scene}" >"${out}/${name}.log" 2>&1 || run_status=$?
  wall=$(difference "${run_start}" "$(seconds)")
  echo "${name},${run_status},${wall},${load}" >>"${out}/runs.csv"
  echo "  ${name}: exit ${run_status}, ${wall} s; $(grep -m1 -E "^gelmpm: (reached|the run|stopped|error)" "${out}/${name}.log" || echo "no summary line")"
  if [[ "${run_status}" -gt 1 ]]; then status=2; fi
}

# Undrained limit: dt and the end of the ramp, 10 dt.
echo "Undrained limit (flat punch):"
for entry in "1e-4|1e-3" "1e-6|1e-5" "1e-8|1e-7" "1e-10|1e-9"; do
  IFS='|' read -r dt ramp <<<"${entry}"
  punch=(--set "Background grid/Cells=30, 30" --set "Material points/Points per cell=3"
         --set "Time stepping/Initial step=${dt}" --set "Time stepping/Step caps=${ramp}: ${dt}"
         --set "Time stepping/End time=${ramp}" --set "Time stepping/Stop at times="
         --set "Boundary conditions/punch/Displacement value/Function expression=0; -0.09 * min(t / ${ramp}, 1)"
         --set "Observables/Chemical potential oscillation=true" --set "Stability/Inertia=true")
  run_case "punch_q2q2sd_dt${dt}" flat_punch.prm "${punch[@]}"
  run_case "punch_q2q2_dt${dt}" flat_punch.prm "${punch[@]}" \
    --set "Discretisation/Chemical potential grid=same"
done

swelling=(--set "Background grid/Upper corner=0.5, 1.5" --set "Background grid/Cells=20, 60"
          --set "Material points/Points per cell=3" --set "Time stepping/End time=0.1"
          --set "Time stepping/Stop at times=" --set "Observables/Boundary condition error=true")
analysis=(--set "Stability/Inertia=true" --set "Stability/Condition number=true")

echo "Nitsche displacement penalty (symmetric, gamma_mu = 25):"
for gamma in 1 10 100 1e3 1e4 1e5 1e6; do
  run_case "symmetric_gu${gamma}_gm25" constrained_swelling.prm "${swelling[@]}" "${analysis[@]}" \
    --set "Nitsche/Displacement penalty=${gamma}"
done

echo "Nitsche chemical-potential penalty (symmetric, gamma_u = 1e3; 25 is the run above):"
for gamma in 0.01 0.1 1 10 100 1e3 1e4 1e5 1e6; do
  run_case "symmetric_gu1e3_gm${gamma}" constrained_swelling.prm "${swelling[@]}" "${analysis[@]}" \
    --set "Nitsche/Chemical potential penalty=${gamma}"
done

echo "Skew-symmetric variant (no stability analysis):"
for gamma in 1 10 100 1e3; do
  run_case "skew_gu${gamma}_gm25" constrained_swelling.prm "${swelling[@]}" \
    --set "Nitsche/Variant=skew-symmetric" --set "Nitsche/Displacement penalty=${gamma}"
done
for gamma in 0.1 1; do
  run_case "skew_gu1e3_gm${gamma}" constrained_swelling.prm "${swelling[@]}" \
    --set "Nitsche/Variant=skew-symmetric" --set "Nitsche/Chemical potential penalty=${gamma}"
done
after_runs=$(seconds)

table_status=0
/usr/bin/python3 "${top}/contrib/benchmarks/extremes_tables.py" "${out}" || table_status=$?
end=$(seconds)
echo "extremes.sh: runs $(difference "${start}" "${after_runs}") s, total $(difference "${start}" "${end}") s wall time; tables in ${out}/extremes.md"
if [[ "${status}" -eq 0 ]]; then status=${table_status}; fi
exit "${status}"
