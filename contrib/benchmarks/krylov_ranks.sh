#!/usr/bin/env bash
# The iterative solver on one and two MPI ranks (doc/performance.md, "Krylov on several MPI
# ranks"): Linear solver/Solver = Krylov with what two ranks run (Displacement preconditioner =
# algebraic, Schur complement = diagonal), each case on 1 rank x 1 thread, 1 rank x 2 threads and
# 2 ranks x 1 thread, a fixed dt so that all solve the same systems:
#   swelling  §4.1 (prm/constrained_swelling.prm) at 80 x 640 cells, 2 steps of 1e-2 tau_d;
#   cube      the free-swelling cube octant (prm/free_swelling_cube.prm) on 52^3 cells, 2 steps
#             of 1e-3 tau_d;
#   cube_2e5  with --large: the octant at h = 0.0125 (52^3 cells over [-0.05, 0.6]^3), 200,000
#             unknowns and 1.8 million points, 2 steps of 1e-3 tau_d, on 1 x 2 and 2 x 1 only
#             (about 45 minutes and 12 GB; doc/scaling.md).
# Prints per run the wall time (s), the peak memory of the mpirun or gelmpm process tree's largest
# process (KB) and gelmpm's summary line; the runs stay in the output directory.
#
#   bash contrib/benchmarks/krylov_ranks.sh [--large] [output directory]
#        (default directory: output/krylov_ranks)
#
# About 6 minutes without --large on a 2-core machine; run it on an otherwise idle machine.
set -euo pipefail

top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
large=false
if [[ ${1:-} == --large ]]; then
  large=true
  shift
fi
out="$(mkdir -p "${1:-output/krylov_ranks}" && cd "${1:-output/krylov_ranks}" && pwd)"
gelmpm="${GELMPM:-${top}/build/gelmpm}"
[[ -x ${gelmpm} ]] || { echo "krylov_ranks.sh: build gelmpm first (bash contrib/setup.sh)"; exit 2; }
mpiexec="${MPIEXEC:-mpirun}"
# Open MPI refuses to start as root (containers) unless told twice.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "${out}"

fixed=(--set "Output/Write particles=false" --set "Time stepping/Growth factor=1"
       --set "Time stepping/Step caps=" --set "Time stepping/Stop at times="
       --set "Time stepping/Tolerance=0" --set "Linear solver/Solver=Krylov"
       --set "Linear solver/Displacement preconditioner=algebraic"
       --set "Linear solver/Schur complement=diagonal")
swelling=("${top}/prm/constrained_swelling.prm" --set "Time stepping/Initial step=1e-2"
          --set "Time stepping/End time=2e-2" --set "Background grid/Cells=80, 640"
          --set "Material points/Points per cell=3")
cube=("${top}/prm/free_swelling_cube.prm" --set "Time stepping/Initial step=1e-3"
      --set "Time stepping/End time=2e-3" --set "Background grid/Cells=52, 52, 52")
cube_2e5=("${cube[@]}" --set "Background grid/Lower corner=-0.05, -0.05, -0.05"
          --set "Background grid/Upper corner=0.6, 0.6, 0.6")

# run NAME RANKS THREADS SCENE-AND-ENTRIES...
run() {
  local name="$1" ranks="$2" threads="$3"
  shift 3
  local launch=("${gelmpm}")
  [[ ${ranks} -gt 1 ]] && launch=("${mpiexec}" -n "${ranks}" --oversubscribe
                                   -x "DEAL_II_NUM_THREADS=${threads}" "${gelmpm}")
  echo "== ${name} ${ranks} x ${threads} (load before: $(cut -d' ' -f1 /proc/loadavg))"
  DEAL_II_NUM_THREADS="${threads}" /usr/bin/time -f "wall %e s, peak %M KB" "${launch[@]}" "$@" \
    "${fixed[@]}" --set "Output/Directory=${name}_${ranks}x${threads}" \
    > "${name}_${ranks}x${threads}.log" 2>&1 || echo "   failed: $(tail -3 "${name}_${ranks}x${threads}.log")"
  grep "Krylov iterations\|^wall" "${name}_${ranks}x${threads}.log" | sed 's/^/   /'
}

for case in swelling cube; do
  declare -n scene="${case}"
  run "${case}" 1 1 "${scene[@]}"
  run "${case}" 1 2 "${scene[@]}"
  run "${case}" 2 1 "${scene[@]}"
done
if ${large}; then
  run cube_2e5 1 2 "${cube_2e5[@]}"
  run cube_2e5 2 1 "${cube_2e5[@]}"
fi
echo "krylov_ranks.sh: runs in ${out}"
