#!/usr/bin/env bash
# Paper §4.3 (swell-induced buckling of a column): the perturbation-amplitude study on a coarse
# grid and the onset against the MPM grid, then Fig. 9/10 with contrib/plotting/column_buckling.py
# (doc/column_buckling.md). Prints the progress and the wall time of every run.
#
#   bash contrib/benchmarks/column_buckling.sh [--paper] [output directory]
#        (default directory: output/column_buckling_study)
#
# Runs (overrides of prm/column_buckling.prm):
#   amplitude_1e-4, amplitude_1e-3, amplitude_1e-2   h_u = H/8 (140 x 80 cells), 3 x 3 points,
#                                                    perturbation 1e-4, 1e-3, 1e-2 H, to 20 tau_d
#                                                    (about 30 s each)
#   onset_h0.1                                       h_u = 0.1H (180 x 100 cells on 18 x 10),
#                                                    4 x 4 points, to 0.3 tau_d (about 1 minute)
#   with --paper: paper                              the scene as it is (h_u = 0.05H, 8 x 8 points,
#                                                    204,800 points) to 2154.4 tau_d (about 10
#                                                    minutes)
#                 onset_h0.025                       h_u = 0.025H (700 x 400 cells), 4 x 4 points
#                                                    (the scene's density, 204,800 points), to
#                                                    0.27 tau_d (a few minutes)
# Writes <run>/ and <run>.log per run, runs.csv (run, exit status, wall seconds) and the figures.
# Needs the build (bash contrib/setup.sh --plotting). Environment: GELMPM_BUILD_DIR (default: build).
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
# shellcheck source=timed_run.sh
source "${top}/contrib/benchmarks/timed_run.sh"
start_study column_buckling "$@"
echo "column_buckling.sh: about $((2 + 10 * paper)) minutes on a 2-core machine; results in ${out}"

summary_pattern="loss of stability between"

coarse=(--set "Background grid/Cells=140, 80" --set "Material points/Points per cell=3"
        --set "Time stepping/Stop at times=0.2, 0.25, 0.3, 0.4, 0.6, 1, 2, 5, 10"
        --set "Time stepping/End time=20")
for amplitude in 1e-4 1e-3 1e-2; do
  run_scene "amplitude_${amplitude}" "${coarse[@]}" --set "Stability/Perturbation amplitude=${amplitude}"
done
run_scene onset_h0.1 --set "Background grid/Upper corner=18, 10" --set "Background grid/Cells=180, 100" \
  --set "Material points/Points per cell=4" --set "Time stepping/End time=0.3"
runs=(--run "1e-3 H=${out}/amplitude_1e-3" --run "1e-4 H=${out}/amplitude_1e-4"
      --run "1e-2 H=${out}/amplitude_1e-2")
snapshots="${out}/amplitude_1e-3"
times="0.2,0.25,0.3,0.4,0.6,1"
if ((paper)); then
  run_scene paper
  run_scene onset_h0.025 --set "Background grid/Cells=700, 400" --set "Material points/Points per cell=4" \
    --set "Time stepping/End time=0.27" --set "Time stepping/Stop at times=0.1, 0.2"
  runs=(--run "paper grid=${out}/paper" "${runs[@]}")
  snapshots="${out}/paper"
  times="0.2,0.28,0.4,1,10,2154.4"
fi
/usr/bin/python3 "${top}/contrib/plotting/column_buckling.py" "${runs[@]}" \
  --snapshots "${snapshots}" --times "${times}" --output "${out}"
echo "column_buckling.sh: figures in ${out}"
