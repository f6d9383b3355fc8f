# Sourced by the benchmark drivers: run_scene NAME [gelmpm arguments...] runs gelmpm on ${scene}
# with its output in ${out}/NAME and its log in ${out}/NAME.log, appends "NAME,exit status,wall
# seconds" to ${out}/runs.csv and prints a line with the log's first match of ${summary_pattern}.
# Needs: build_dir, scene, out, summary_pattern.

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
