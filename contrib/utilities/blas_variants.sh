#!/usr/bin/env bash
# Runs the whole test suite once per BLAS variant, to show that no test hinges on round-off: OpenBLAS
# picks its kernels by processor, and a test whose assertion a different kernel or thread count
# can flip passes on one machine and fails on another.
#
#   bash contrib/utilities/blas_variants.sh [variant...]
#
# A variant is <OPENBLAS_CORETYPE>:<threads>, with "default" for the kernel OpenBLAS picks itself;
# without arguments: default:1 Haswell:2 Prescott:1 (AVX2, and SSE3 only: kernels that differ
# from those of a current processor's AVX-512; Haswell's with one thread once flipped a test).
# Each run re-runs every test (the stored results of the deal.II-style cases are removed first)
# and prints ctest's summary; a log per variant goes to <build>/blas-<variant>.log. Exit status: the number of variants that failed.
# Environment: GELMPM_BUILD_DIR (default: build, which contrib/setup.sh makes).
set -uo pipefail
top="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${GELMPM_BUILD_DIR:-${top}/build}"
[[ -f "${build_dir}/CMakeCache.txt" ]] || { echo "error: no build in ${build_dir}: run contrib/setup.sh first" >&2; exit 1; }
variants=("$@")
((${#variants[@]})) || variants=(default:1 Haswell:2 Prescott:1)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
failed=0
for variant in "${variants[@]}"; do
  kernel=${variant%%:*}
  threads=${variant##*:}
  [[ $threads =~ ^[1-9][0-9]*$ ]] || { echo "error: '$variant': the thread count after ':' must be a positive integer" >&2; exit 1; }
  cmake -DGELMPM_TEST_BLAS_THREADS="${threads}" "${build_dir}" >/dev/null
  find "${build_dir}/tests" -path '*.release/output' -o -path '*.release/diff' | xargs -r rm -f
  log="${build_dir}/blas-${kernel}-${threads}.log"
  if [[ $kernel == default ]]; then
    (cd "${build_dir}" && env -u OPENBLAS_CORETYPE ctest -j "$(nproc)" --output-on-failure) >"${log}" 2>&1
  else
    (cd "${build_dir}" && OPENBLAS_CORETYPE="${kernel}" ctest -j "$(nproc)" --output-on-failure) >"${log}" 2>&1
  fi
  status=$?
  echo "${variant}: $(grep -E 'tests passed' "${log}" | tail -n 1) (log: ${log})"
  ((status == 0)) || { failed=$((failed + 1)); grep -E '^\s+[0-9]+ - ' "${log}"; }
done
cmake -DGELMPM_TEST_BLAS_THREADS=1 "${build_dir}" >/dev/null
exit "${failed}"
