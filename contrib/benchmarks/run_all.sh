#!/bin/bash
# Every benchmark of doc/performance.md and doc/fem_peer.md, one after the other:
#
#   bash contrib/benchmarks/run_all.sh           # full: about 95 min on a 2-core machine
#   bash contrib/benchmarks/run_all.sh --quick   # quick: under 10 min
#
# Full: the §4.1 speed-accuracy sweeps (speed_accuracy.py, 3 repeats per run), the flat-punch sweep
# (flat_punch_sweep.py, 3 repeats), the body-fitted FE peer on §4.1 (fem_peer.py) and on the flat
# punch with its depth study (fem_peer_flat_punch.py), the error-control study (tolerance_study.py,
# full mode only). Quick: the same four in their quick modes
# (fewer levels, shorter runs; errors of quick runs are not comparable with full runs).
# Results go to output/ (each script prints where); the binaries are copied to output/bench-bin
# first, so that a rebuild during the runs cannot change what is measured. Run it on an otherwise
# idle machine: the scripts record the load average, but cannot undo it.
set -euo pipefail
cd "$(dirname "$0")/../.."
quick=""
case "${1:-}" in
  "") ;;
  --quick) quick="--quick" ;;
  *) echo "usage: bash contrib/benchmarks/run_all.sh [--quick]" >&2; exit 2 ;;
esac
for program in gelmpm gelmpm-swelling-1d gelmpm-fem-swelling gelmpm-fem-flat-punch; do
  if [ ! -x "build/$program" ]; then
    echo "run_all.sh: build/$program is missing; build first (bash contrib/test.sh builds everything)" >&2
    exit 1
  fi
done
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p output/bench-bin
cp build/gelmpm build/gelmpm-swelling-1d build/gelmpm-fem-swelling build/gelmpm-fem-flat-punch \
  output/bench-bin/
export GELMPM_BUILD_DIR="$PWD/output/bench-bin"
if [ -n "$quick" ]; then
  echo "run_all.sh: quick mode, about 8 min on a 2-core machine"
  fem_peer_options=(--no-mpm --output output/fem_peer_quick)
else
  echo "run_all.sh: full mode, about 95 min on a 2-core machine (each script prints its own estimate)"
  fem_peer_options=(--mpm-repeats 3 --output output/fem_peer)
fi
start=$(date +%s)
/usr/bin/python3 contrib/benchmarks/speed_accuracy.py $quick
/usr/bin/python3 contrib/benchmarks/flat_punch_sweep.py $quick --build "$GELMPM_BUILD_DIR" \
  --output "output/flat_punch_sweep${quick:+_quick}"
/usr/bin/python3 contrib/benchmarks/fem_peer.py --build "$GELMPM_BUILD_DIR" "${fem_peer_options[@]}"
/usr/bin/python3 contrib/benchmarks/fem_peer_flat_punch.py $quick --build "$GELMPM_BUILD_DIR" \
  --output "output/fem_peer_flat_punch${quick:+_quick}"
# The error-control study has no quick mode: its loose tolerances are the quick part.
[[ -z $quick ]] && /usr/bin/python3 contrib/benchmarks/tolerance_study.py
echo "run_all.sh: finished in $(( ($(date +%s) - start) / 60 )) min $(( ($(date +%s) - start) % 60 )) s"
