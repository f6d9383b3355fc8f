#!/usr/bin/env bash
# One rank with two threads against two MPI ranks with one thread each, on this machine's two
# cores: §4.1 at the paper setting (prm/constrained_swelling.prm, to its end) and the §4.3 column
# at paper resolution (prm/column_buckling.prm, stability analysis at every step) through the
# bracketing of its loss of stability (to 0.3 tau_d). Per run: wall time, steps, Newton
# iterations, peak memory (largest rank and all ranks, as gelmpm reports them), the share of each
# phase (TimerOutput of rank 0), and whether the two-rank statistics agree with the one-rank ones
# (gelmpm-compare-statistics). Writes <output>/scaling.md and, with --update-doc, the table into
# doc/scaling.md between the markers "scaling: begin" and "scaling: end".
#
#   bash contrib/benchmarks/scaling.sh [--update-doc] [output directory]
#        (default directory: output/scaling)
#
# Run it on an otherwise idle machine (the table records the load average before each run).
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "${top}/contrib/benchmarks/doc_driver.sh"
doc_driver_arguments scaling "$@"
# Open MPI refuses root unless told twice (containers).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "scaling.sh: about 6 minutes on a 2-core machine; results in ${out}"

# run_case NAME RANKS SCENE [--set ...]
run_case() {
  local name="$1" ranks="$2" scene="$3"
  shift 3
  local launcher=()
  [[ ${ranks} -gt 1 ]] && launcher=(mpiexec -n "${ranks}" --oversubscribe)
  echo "  ${name}: started $(date +%H:%M:%S), load average $(cut -d' ' -f1 /proc/loadavg)"
  cut -d' ' -f1 /proc/loadavg > "${out}/${name}.load"
  set +e
  /usr/bin/time -f "%e" -o "${out}/${name}.time" "${launcher[@]}" "${build_dir}/gelmpm" \
    "${top}/prm/${scene}" --set "Output/Directory=${out}/${name}" \
    --set "Output/Write particles=false" "$@" > "${out}/${name}.log" 2>&1
  echo $? > "${out}/${name}.status"
  set -e
}

column=(--set "Time stepping/End time=0.3")
run_case swelling_1x2 1 constrained_swelling.prm
run_case swelling_2x1 2 constrained_swelling.prm
run_case column_1x2 1 column_buckling.prm "${column[@]}"
run_case column_2x1 2 column_buckling.prm "${column[@]}"

# The share of a TimerOutput section in a log, in percent.
share() {
  awk -v section="$2" -F'|' '$2 ~ "^ *"section" *$" {gsub(/[ %]/, "", $5); print $5}' "$1" | tail -1
}

table="${out}/scaling.md"
{
  echo "| run | ranks x threads | wall time | steps | Newton iterations | peak memory: largest rank / all ranks | setup | assembly | solve | stability | update | statistics against 1 rank | load before |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  for scene in swelling column; do
    for layout in 1x2 2x1; do
      name="${scene}_${layout}"
      log="${out}/${name}.log"
      status=$(cat "${out}/${name}.status")
      wall=$(cat "${out}/${name}.time" | tail -1)
      steps=$(sed -n 's/.*reached t\/tau_d = .* in \([0-9]*\) steps.*/\1/p' "${log}" | tail -1)
      newton=$(sed -n 's/^gelmpm: \([0-9]*\) Newton iterations.*/\1/p' "${log}" | tail -1)
      memory=$(sed -n 's/^gelmpm: peak memory \(.*\)$/\1/p' "${log}" | tail -1)
      agree="-"
      if [[ ${layout} == 2x1 ]]; then
        if "${build_dir}/gelmpm-compare-statistics" "${out}/${scene}_1x2/statistics.csv" \
          "${out}/${name}/statistics.csv" > "${out}/${name}.compare" 2>&1; then
          agree="agree (1e-10)"
        else
          agree="differ: $(grep -c '^FAIL' "${out}/${name}.compare") column(s)"
        fi
      fi
      [[ ${status} -eq 0 ]] || wall="${wall} (exit ${status})"
      echo "| ${scene} | ${layout/x/ x } | ${wall} s | ${steps} | ${newton} | ${memory} | $(share "${log}" setup) % | $(share "${log}" assembly) % | $(share "${log}" solve) % | $(share "${log}" stability) % | $(share "${log}" update) % | ${agree} | $(cat "${out}/${name}.load") |"
    done
  done
} > "${table}"
cat "${table}"

if [[ ${update_doc} -eq 1 ]]; then
  write_between_markers "${top}/doc/scaling.md" scaling "${table}"
fi
