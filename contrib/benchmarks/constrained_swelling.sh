#!/usr/bin/env bash
# Paper §4.1 (constrained one-dimensional swelling), end to end: runs the full MPM scene
# prm/constrained_swelling.prm (t to 1713 tau_d) and the finite-difference reference
# gelmpm-swelling-1d into one directory, then makes Fig. 6b/6c and the agreement and cost tables
# with contrib/plotting/constrained_swelling.py. Prints the time each part took.
#
#   bash contrib/benchmarks/constrained_swelling.sh [output directory]   (default: output/benchmark_constrained_swelling)
#
# Writes into the directory: mpm/ (statistics.csv, particles.pvd, particles-*.vtu), gelmpm.log,
# reference/ (reference_thickness.csv, reference_profiles.csv), reference.log, the PNGs,
# agreement.md/.csv and cost.md. Exit status: that of the plotting script (1 if a target of the
# agreement table is missed), or the first failing step's.
# Needs the build (bash contrib/setup.sh --plotting) and /usr/bin/python3 with numpy, matplotlib, vtk.
# Environment: GELMPM_BUILD_DIR (default: build).
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${GELMPM_BUILD_DIR:-${top}/build}"
out="${1:-${top}/output/benchmark_constrained_swelling}"
mkdir -p "${out}"
out="$(cd "${out}" && pwd)"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

for binary in gelmpm gelmpm-swelling-1d; do
  [[ -x "${build_dir}/${binary}" ]] || { echo "error: ${build_dir}/${binary} missing; run bash contrib/setup.sh --plotting" >&2; exit 2; }
done

seconds() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f s", b - a }'; }

start=$(seconds)
echo "MPM: ${build_dir}/gelmpm --set \"Output/Directory=${out}/mpm\" prm/constrained_swelling.prm"
"${build_dir}/gelmpm" --set "Output/Directory=${out}/mpm" "${top}/prm/constrained_swelling.prm" >"${out}/gelmpm.log"
after_mpm=$(seconds)
grep -E "^gelmpm: reached" "${out}/gelmpm.log" || true
echo "  MPM run: $(elapsed "${start}" "${after_mpm}") wall time (log: ${out}/gelmpm.log)"

# 4000 log-spaced samples of Delta h so that interpolating at the MPM step times adds nothing
# visible (the solver's own steps do not depend on the sampling).
echo "Reference: ${build_dir}/gelmpm-swelling-1d --samples 4000 --output ${out}/reference"
"${build_dir}/gelmpm-swelling-1d" --samples 4000 --output "${out}/reference" >"${out}/reference.log"
after_reference=$(seconds)
tail -n 2 "${out}/reference.log" | head -n 1
echo "  reference: $(elapsed "${after_mpm}" "${after_reference}") wall time"

status=0
/usr/bin/python3 "${top}/contrib/plotting/constrained_swelling.py" --mpm "${out}/mpm" \
  --reference "${out}/reference" --log "${out}/gelmpm.log" --output "${out}" || status=$?
end=$(seconds)
echo "  plots and tables: $(elapsed "${after_reference}" "${end}") wall time"
echo "constrained_swelling.sh: total $(elapsed "${start}" "${end}") wall time; results in ${out}"
exit "${status}"
