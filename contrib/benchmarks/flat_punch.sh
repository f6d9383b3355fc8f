#!/usr/bin/env bash
# Paper §4.2 (flat punch indentation), end to end: runs prm/flat_punch.prm with the four u-mu
# discretisations of the paper, the observable mu_oscillation on, each into its own directory, then
# makes Fig. 7b/7c, the Fig. 8-like panel and the table with contrib/plotting/flat_punch.py.
# Prints the progress and the wall time of every run (doc/flat_punch.md).
#
#   bash contrib/benchmarks/flat_punch.sh [--quick] [--refined] [output directory]
#        (default directory: output/flat_punch_study)
#
#   --quick    stop every run at t = 0.1 tau_d (the two times of Fig. 7 and 8) instead of the
#              paper's 2300 tau_d; the drained-limit check of the table is then left open
#   --refined  also run, to the end of the ramp t_inc only, the pairs on the next finer grids:
#              Q2-Q2 and Q3-Q2 with h_u = h_mu = 0.025H, Q2-Q2SD with h_u = 0.0125H, h_mu = 0.025H
#              (sparse direct solver MUMPS, much faster than KLU there; adds fig7b_refinement.png)
#
# The runs (overrides of prm/flat_punch.prm, whose header lists them):
#   q2_q2            (i)   Q2-Q2,          h_u = h_mu = 0.05H
#   q3_q2            (ii)  Q3-Q2,          h_u = h_mu = 0.05H
#   q2_q2sd_fine     (iii) Q2-Q2SD fine,   h_u = 0.025H, h_mu = 0.05H (the file as it is)
#   q2_q2sd_coarse   (iv)  Q2-Q2SD coarse, h_u = 0.05H,  h_mu = 0.1H
#   with --refined:  q2_q2_h0.025, q3_q2_h0.025, q2_q2sd_h0.0125
#
# Writes into the directory: <run>/ (statistics.csv, particles.pvd, particles-*.vtu, parameters.prm),
# <run>.log (gelmpm's stdout and stderr), runs.csv (run, label, end time, exit status, wall seconds,
# 1-minute load average at the start of the run), and what the plotting script writes
# (fig7b_*.png, fig7c_*.png, fig8_*.png, flat_punch_table.csv/.md).
# Exit status: 0 if every run completed and the plots were made, else the first non-zero status.
# Needs the build (bash contrib/setup.sh --plotting) and /usr/bin/python3 with numpy, matplotlib, vtk.
# Environment: GELMPM_BUILD_DIR (default: build).
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${GELMPM_BUILD_DIR:-${top}/build}"
end_time=2300
refined=0
out=""
for argument in "$@"; do
  case "${argument}" in
    --quick) end_time=0.1 ;;
    --refined) refined=1 ;;
    -h | --help) sed -n '2,29p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "error: unknown option ${argument} (see --help)" >&2; exit 2 ;;
    *) out="${argument}" ;;
  esac
done
out="${out:-${top}/output/flat_punch_study}"
mkdir -p "${out}"
out="$(cd "${out}" && pwd)"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

[[ -x "${build_dir}/gelmpm" ]] || { echo "error: ${build_dir}/gelmpm missing; run bash contrib/setup.sh --plotting" >&2; exit 2; }

seconds() { date +%s.%N; }
difference() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }

t_inc=3.125e-6
coarse=("Background grid/Cells=30, 30")
same=("Discretisation/Chemical potential grid=same")
cubic=("Discretisation/Displacement degree=3")
mumps=("Linear solver/Solver=MUMPS")
# name | label | end time | overrides (separated by ';')
cases=(
  "q2_q2|(i) Q2-Q2|${end_time}|${coarse[0]};${same[0]}"
  "q3_q2|(ii) Q3-Q2|${end_time}|${coarse[0]};${same[0]};${cubic[0]}"
  "q2_q2sd_fine|(iii) Q2-Q2SD fine|${end_time}|"
  "q2_q2sd_coarse|(iv) Q2-Q2SD coarse|${end_time}|${coarse[0]}"
)
if [[ "${refined}" -eq 1 ]]; then
  cases+=(
    "q2_q2_h0.025|Q2-Q2 h=0.025H|${t_inc}|${same[0]};${mumps[0]}"
    "q3_q2_h0.025|Q3-Q2 h=0.025H|${t_inc}|${same[0]};${cubic[0]};${mumps[0]}"
    "q2_q2sd_h0.0125|Q2-Q2SD h_u=0.0125H|${t_inc}|Background grid/Cells=120, 120;${mumps[0]}"
  )
fi

echo "flat_punch.sh: ${#cases[@]} runs of prm/flat_punch.prm into ${out}"
echo "  binary: ${build_dir}/gelmpm"
echo "run,label,end_time,exit_status,wall_seconds,load_average" >"${out}/runs.csv"
status=0
start=$(seconds)
k=0
for entry in "${cases[@]}"; do
  k=$((k + 1))
  IFS='|' read -r name label run_end_time override_list <<<"${entry}"
  arguments=(--set "Output/Directory=${out}/${name}" --set "Observables/Chemical potential oscillation=true"
             --set "Time stepping/End time=${run_end_time}")
  shown=""
  if [[ -n "${override_list}" ]]; then
    IFS=';' read -r -a overrides <<<"${override_list}"
    for override in "${overrides[@]}"; do
      arguments+=(--set "${override}")
      shown+=" --set \"${override}\""
    done
  fi
  load=$(cut -d ' ' -f 1 /proc/loadavg)
  rm -rf "${out:?}/${name}"
  echo "[${k}/${#cases[@]}] ${label} to t = ${run_end_time} tau_d (load average ${load}):"
  echo "      gelmpm${shown} --set \"Time stepping/End time=${run_end_time}\" prm/flat_punch.prm"
  run_start=$(seconds)
  run_status=0
  "${build_dir}/gelmpm" "${arguments[@]}" "${top}/prm/flat_punch.prm" >"${out}/${name}.log" 2>&1 || run_status=$?
  run_end=$(seconds)
  wall=$(difference "${run_start}" "${run_end}")
  echo "${name},${label},${run_end_time},${run_status},${wall},${load}" >>"${out}/runs.csv"
  grep -E "^gelmpm: (reached|error|the run|stopped)" "${out}/${name}.log" | sed 's/^/      /' || true
  echo "      exit status ${run_status}, ${wall} s wall time (log: ${out}/${name}.log)"
  if [[ "${run_status}" -ne 0 && "${status}" -eq 0 ]]; then status=${run_status}; fi
done
after_runs=$(seconds)

plot_status=0
/usr/bin/python3 "${top}/contrib/plotting/flat_punch.py" --study "${out}" --output "${out}" || plot_status=$?
end=$(seconds)
echo "  plots and table: $(difference "${after_runs}" "${end}") s wall time"
echo "flat_punch.sh: total $(difference "${start}" "${end}") s wall time; results in ${out}"
if [[ "${status}" -eq 0 ]]; then status=${plot_status}; fi
exit "${status}"
