# GMRES with AMG and the approximate Schur complement (Linear solver/Solver = Krylov, Displacement
# preconditioner = algebraic; geometric_multigrid.sh checks the geometric one) solves the
# same Newton systems as MUMPS: the runs must take the same steps with the same Newton iterations
# (within one: modified Newton's reuse decisions see residuals at the linear tolerance) and give
# the same physical statistics to 1e-6 of each column's largest value (each solve reduces the
# residual by 1e-8; Newton stops at its own tolerance). Checked on
# - §4.1 (prm/constrained_swelling.prm) to 0.1 tau_d with the paper's step control: 27 steps,
#   115 Newton iterations, five sparsity patterns as the layer swells into new cells (to 0.5 tau_d,
#   59 steps and nine patterns, at twice the CPU time), with 4 points per cell and direction
#   instead of the scene's 6 (the same steps and patterns, 116 Newton iterations, at 1.5 times
#   the CPU time);
# - the undrained limit, 3 steps of dt = 1e-6 tau_d on §4.1, where the mu block C vanishes and
#   the Schur approximation rests on the coupling alone: at most 12 Krylov iterations per solve
#   with the default (LSC, measured 9.6), and the old approximation ('Schur complement =
#   diagonal') still agrees with MUMPS, in at most 42 (measured 35.3);
# - 3D, 2 steps of the free-swelling cube (prm/free_swelling_cube.prm) at 14^3 cells: the AMG
#   with six rigid-body modes;
# - a locally refined grid (prm/constrained_swelling_front.prm: the cells of the mu front halved,
#   marked anew every step), 10 steps of 0.01 tau_d with 4 points per cell: the leaves' points
#   split where the front arrives and merge where it leaves (the points' count must rise and fall),
#   so the pattern and the AMG's unknowns change from step to step; the geometric multigrid asked
#   for, the algebraic one taken (the uniform grids' levels do not know the leaves);
# (tests/mpi/krylov.sh compares Krylov on two MPI ranks with one).
# Same arguments as the MPI tests (gelmpm, compare tool, mpiexec, source directory).
source "$(dirname "${BASH_SOURCE[0]}")/../mpi/common.sh"
# run NAME SCENE [--set ...]: one run with each solver, NAME_MUMPS and NAME_Krylov.
run() {
  local name="$1" scene="$2"
  shift 2
  for solver in MUMPS Krylov; do
    "$gelmpm" "$source_dir/prm/$scene" --set "Output/Directory=${name}_${solver}" \
      --set "Output/Write particles=false" --set "Linear solver/Solver=${solver}" \
      --set "Linear solver/Displacement preconditioner=algebraic" "$@" \
      > "${name}_${solver}.log" 2>&1
    check $? "$name with $solver finished ($(grep -m1 'reached\|error\|failed' "${name}_${solver}.log"))"
  done
  "$compare" --relative 1e-6 --newton 1 "${name}_MUMPS/statistics.csv" "${name}_Krylov/statistics.csv" \
    > "${name}_compare.log"
  check $? "$name: Krylov and MUMPS statistics agree ($(tail -1 "${name}_compare.log"))"
}

run swelling constrained_swelling.prm --set "Material points/Points per cell=4" \
  --set "Time stepping/End time=0.1" \
  --set "Time stepping/Stop at times=0.1"
fixed_steps 1e-6 3
run undrained constrained_swelling.prm "${steps[@]}"
per_solve=$(grep -o "([0-9.e+-]* per solve)" undrained_Krylov.log | tr -d '(' | awk '{print $1}')
awk -v p="${per_solve:-1e9}" 'BEGIN { exit !(p <= 12) }'
check $? "undrained limit: ${per_solve:-no} Krylov iterations per solve (at most 12)"
"$gelmpm" "$source_dir/prm/constrained_swelling.prm" --set "Output/Directory=undrained_diagonal" \
  --set "Output/Write particles=false" --set "Linear solver/Solver=Krylov" \
  --set "Linear solver/Displacement preconditioner=algebraic" \
  --set "Linear solver/Schur complement=diagonal" "${steps[@]}" > undrained_diagonal.log 2>&1
check $? "undrained with 'Schur complement = diagonal' finished ($(grep -m1 'reached\|error\|failed' undrained_diagonal.log))"
"$compare" --relative 1e-6 --newton 1 undrained_MUMPS/statistics.csv \
  undrained_diagonal/statistics.csv > undrained_diagonal_compare.log
check $? "undrained, diagonal: Krylov and MUMPS statistics agree ($(tail -1 undrained_diagonal_compare.log))"
per_solve=$(grep -o "([0-9.e+-]* per solve)" undrained_diagonal.log | tr -d '(' | awk '{print $1}')
awk -v p="${per_solve:-1e9}" 'BEGIN { exit !(p <= 42) }'
check $? "undrained limit, diagonal: ${per_solve:-no} Krylov iterations per solve (at most 42)"
fixed_steps 0.01 10
run front constrained_swelling_front.prm "${steps[@]}" --set "Time stepping/Tolerance=0" \
  --set "Material points/Points per cell=4" \
  --set "Linear solver/Displacement preconditioner=geometric"
grep -q "Krylov iterations in .*displacement block by algebraic multigrid" front_Krylov.log
check $? "refined grid: the displacement block by the algebraic multigrid"
points() { statistic front_Krylov/statistics.csv n_particles "$1"; }
[[ $(points 4) -gt $(points 2) && $(points 10) -lt $(points 4) ]]
check $? "refined grid: points split and merged ($(points 2), $(points 4), $(points 10))"
fixed_steps 0.01 2
run cube free_swelling_cube.prm "${steps[@]}" --set "Background grid/Cells=14, 14, 14" \
  --set "Time stepping/Tolerance=0"

finish
