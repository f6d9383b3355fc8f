# Linear solver/Solver = automatic (the default) chooses by MUMPS's own estimate of its
# factorisation against 'Automatic memory share' of the memory available:
# - on §4.1 (prm/constrained_swelling.prm, 3 steps of 1e-4 tau_d) with the default share it
#   chooses MUMPS, says so with the estimate, and gives MUMPS's statistics bit for bit;
# - with a share that holds three quarters of that estimate it chooses MUMPS in single precision
#   (half the factors' memory), says so, and gives MUMPS's statistics to 1e-6;
# - with a share so small that no factorisation fits (1e-12) it chooses Krylov, says so, and gives
#   MUMPS's statistics to 1e-6 of each column's largest value (the Krylov tolerance 1e-8);
# - on two MPI ranks with that share it chooses Krylov too (all ranks' estimate against the least
#   memory available), says so, and gives MUMPS's statistics to 1e-6.
# Same arguments as the MPI tests (gelmpm, compare tool, mpiexec, source directory).
source "$(dirname "${BASH_SOURCE[0]}")/../mpi/common.sh"
scene="$source_dir/prm/constrained_swelling.prm"
steps=(--set "Output/Write particles=false" --set "Time stepping/Initial step=1e-4"
       --set "Time stepping/Growth factor=1" --set "Time stepping/Step caps="
       --set "Time stepping/Stop at times=" --set "Time stepping/End time=3e-4")
# run NAME [--set ...]
run() {
  local name="$1"
  shift
  "$gelmpm" "$scene" --set "Output/Directory=$name" "${steps[@]}" "$@" > "$name.log" 2>&1
  check $? "$name finished ($(grep -m1 'reached\|error\|failed' "$name.log"))"
}
run mumps --set "Linear solver/Solver=MUMPS"
run chosen_direct
grep -q "automatic: MUMPS.*; MUMPS: the factorisation's estimate [0-9.e+]* MB" chosen_direct.log
check $? "default share: automatic chose MUMPS and said why ($(grep -o 'automatic: [^)]*' chosen_direct.log | head -1))"
"$compare" --relative 1e-12 mumps/statistics.csv chosen_direct/statistics.csv > direct_compare.log
check $? "automatic (MUMPS) and MUMPS statistics agree to 1e-12 ($(tail -1 direct_compare.log))"
# Three quarters of the estimate, from the numbers the direct choice printed.
share=$(grep -o "estimate [0-9.e+]* MB against [0-9.e+]* MB ([0-9.e+]* of [0-9.e+]* MB" chosen_direct.log |
  head -1 | awk '{ print 0.75 * $2 / $9 }')
run chosen_single --set "Linear solver/Automatic memory share=${share:-0}"
grep -q "automatic: MUMPS LDL^T.*single precision.*; MUMPS in single precision: the factorisation's estimate .*half of it fits" chosen_single.log
check $? "share ${share:-none}: automatic chose single precision and said why ($(grep -o 'MUMPS in single precision: [^)]*)' chosen_single.log | head -1))"
"$compare" --relative 1e-6 --newton 1 mumps/statistics.csv chosen_single/statistics.csv > single_compare.log
check $? "automatic (single precision) and MUMPS statistics agree to 1e-6 ($(tail -1 single_compare.log))"
run chosen_krylov --set "Linear solver/Automatic memory share=1e-12"
grep -q "automatic: GMRES with AMG and Schur; Krylov: the factorisation's estimate" chosen_krylov.log
check $? "share 1e-12: automatic chose Krylov and said why"
grep -q "Krylov iterations in" chosen_krylov.log
check $? "share 1e-12: the Newton systems were solved by Krylov"
"$compare" --relative 1e-6 --newton 1 mumps/statistics.csv chosen_krylov/statistics.csv > krylov_compare.log
check $? "automatic (Krylov) and MUMPS statistics agree to 1e-6 ($(tail -1 krylov_compare.log))"
"$mpiexec" -n 2 --oversubscribe "$gelmpm" "$scene" --set "Output/Directory=two_ranks" "${steps[@]}" \
  --set "Linear solver/Automatic memory share=1e-12" > two_ranks.log 2>&1
check $? "two ranks: automatic runs ($(grep -m1 'reached\|error' two_ranks.log))"
grep -q "automatic: GMRES with AMG and Schur; Krylov: the factorisation's estimate" two_ranks.log
check $? "two ranks, share 1e-12: automatic chose Krylov and said why"
"$compare" --relative 1e-6 --newton 1 mumps/statistics.csv two_ranks/statistics.csv > two_ranks_compare.log
check $? "two ranks: automatic (Krylov) and MUMPS statistics agree to 1e-6 ($(tail -1 two_ranks_compare.log))"
finish
