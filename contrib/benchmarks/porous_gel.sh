#!/usr/bin/env bash
# Paper §4.4 (pattern transformation of a gel with a square lattice of holes): the two readings of
# t_inc and the two contact methods on the coarse grid, the scene on three grids, then Fig. 11-13
# with contrib/plotting/porous_gel.py (doc/porous_gel.md). Prints the progress, the wall time and
# the last event of every run.
#
#   bash contrib/benchmarks/porous_gel.sh [--paper] [output directory]
#        (default directory: output/porous_gel_study)
#
# Runs (overrides of prm/porous_gel.prm):
#   coarse_penalty      h_u = R/18 (40 x 40 cells), 5 x 5 points, to 576.3 tau_d (about 1.5 minutes)
#   coarse_nitsche      the same with 'Contact/Method = nitsche' (stops near 264 tau_d; 2 minutes)
#   coarse_fast_ramp    the same as coarse_penalty with t_inc = 1.511 tau_d, to 20 tau_d (2 minutes)
#   h18                 h_u = R/18, 10 x 10 points (the scene's density), to 576.3 tau_d (3.5 minutes)
#   with --paper: h36   the scene as it is (h_u = R/36, 233,332 points; about 8 minutes)
#                 h72   h_u = R/72 (160 x 160 cells, 932,360 points) to 118 tau_d, just past the
#                       self-contact, where its steps shrink to 1e-4 tau_d (doc/porous_gel.md,
#                       "Three grids"; about 35 minutes)
# Writes <run>/ and <run>.log per run, runs.csv (run, exit status, wall seconds) and the figures.
# Needs the build (bash contrib/setup.sh --plotting). Environment: GELMPM_BUILD_DIR (default: build).
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
# shellcheck source=timed_run.sh
source "${top}/contrib/benchmarks/timed_run.sh"
start_study porous_gel "$@"
echo "porous_gel.sh: about $((9 + 45 * paper)) minutes on a 2-core machine; results in ${out}"
summary_pattern="reached t/tau_d\|cannot converge\|the run stopped\|the run failed"

coarse=(--set "Background grid/Cells=40, 40" --set "Material points/Points per cell=5"
        --set "Output/Interval steps=20")
run_scene coarse_penalty "${coarse[@]}"
run_scene coarse_nitsche "${coarse[@]}" --set "Contact/Method=nitsche"
run_scene coarse_fast_ramp "${coarse[@]}" --set "Time stepping/End time=20" \
  --set "Boundary conditions/holes/Chemical potential value/Function constants=mu0=-0.14597453, tinc=1.511"
run_scene h18 --set "Background grid/Cells=40, 40" --set "Output/Interval steps=10"
runs=(--run "h_u = R/18=${out}/h18")
snapshots="${out}/h18"
if ((paper)); then
  run_scene h36 --set "Output/Interval steps=10"
  run_scene h72 --set "Background grid/Cells=160, 160" --set "Output/Interval steps=50" \
    --set "Time stepping/End time=118"
  runs=(--run "h_u = R/36=${out}/h36" "${runs[@]}")
  snapshots="${out}/h36"
fi
for run in coarse_penalty coarse_nitsche coarse_fast_ramp h18 h36 h72; do
  [[ -f "${out}/${run}/events.csv" ]] && { echo "${run}:"; cat "${out}/${run}/events.csv"; }
done
/usr/bin/python3 "${top}/contrib/plotting/porous_gel.py" "${runs[@]}" --snapshots "${snapshots}" \
  --output "${out}"
echo "porous_gel.sh: figures in ${out}"
