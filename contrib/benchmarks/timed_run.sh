# Sourced by the benchmark drivers of one scene, after setting top:
#   start_study NAME "$@"  reads the driver's arguments ([--paper] [output directory]), sets
#                          build_dir, paper (0 or 1), out (default output/NAME_study) and scene
#                          (prm/NAME.prm), and starts ${out}/runs.csv;
#   run_scene RUN [gelmpm arguments...]  runs gelmpm on ${scene} with its output in ${out}/RUN and
#                          its log in ${out}/RUN.log, appends "RUN,exit status,wall seconds" to
#                          ${out}/runs.csv and prints a line with the log's first match of
#                          ${summary_pattern}.

start_study() {
  local name="$1"
  shift
  build_dir="${GELMPM_BUILD_DIR:-${top}/build}"
  paper=0
  out=""
  for argument in "$@"; do
    case "${argument}" in
      --paper) paper=1 ;;
      *) out="${argument}" ;;
    esac
  done
  out="${out:-${top}/output/${name}_study}"
  mkdir -p "${out}"
  scene="${top}/prm/${name}.prm"
  echo "run,exit_status,wall_seconds" > "${out}/runs.csv"
}

run_scene() {
  local name="$1"
  shift
  local start status wall
  start=$(date +%s%N)
  set +e
  "${build_dir}/gelmpm" "${scene}" --set "Output/Directory=${out}/${name}" "$@" > "${out}/${name}.log" 2>&1
  status=$?
  set -e
  wall=$(awk -v a="${start}" -v b="$(date +%s%N)" 'BEGIN { printf "%.1f", (b - a) / 1e9 }')
  echo "${name},${status},${wall}" >> "${out}/runs.csv"
  echo "  ${name}: exit ${status}, ${wall} s; $(grep -m1 "${summary_pattern}" "${out}/${name}.log" || echo "no line with '${summary_pattern}'")"
}
