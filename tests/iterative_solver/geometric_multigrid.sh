# The geometric multigrid on the displacement block (Linear solver/Displacement preconditioner =
# geometric: the nested B-spline grids) inside the iterative solver, against MUMPS:
# - §4.1 (prm/constrained_swelling.prm) on 40 x 320 cells, 3 points per cell, 3 steps of fixed dt
#   in the undrained limit (dt = 1e-6 tau_d), where the count is highest (at dt = 1e2 tau_d it is
#   6.7; doc/performance.md has it, the test leaves it out for time);
# - 3D, one step of dt = 1e-3 of the free-swelling cube (prm/free_swelling_cube.prm) on 20^3
#   cells (3 Newton iterations; with a second step, 2 more, 15.6 per solve at 1.5 times the CPU);
# with 'Multigrid coarse size' low (300) so that the cycles have 3 or 4 levels. Each run must take
# the steps and Newton iterations of the MUMPS run (within one), give its statistics to 1e-6 of
# each column's largest value, use the geometric multigrid, and at most so many Krylov iterations
# per solve: undrained 20 (measured 16.5 with the default Schur approximation, LSC; with A solved
# exactly 10.7; the old 'diagonal' one took 54.3, 53.8 with A exact), cube 19 (measured 15.3;
# 'diagonal' 27.3).
# Same arguments as the MPI tests (gelmpm, compare tool, mpiexec, source directory).
source "$(dirname "${BASH_SOURCE[0]}")/../mpi/common.sh"
# run NAME MAX SCENE [--set ...]: MUMPS and Krylov with the geometric multigrid, compared.
run() {
  local name="$1" max="$2" scene="$3"
  shift 3
  "$gelmpm" "$source_dir/prm/$scene" --set "Output/Directory=${name}_MUMPS" \
    --set "Output/Write particles=false" --set "Linear solver/Solver=MUMPS" "$@" \
    > "${name}_MUMPS.log" 2>&1
  check $? "$name with MUMPS finished ($(grep -m1 'reached\|error\|failed' "${name}_MUMPS.log"))"
  "$gelmpm" "$source_dir/prm/$scene" --set "Output/Directory=${name}_GMG" \
    --set "Output/Write particles=false" --set "Linear solver/Solver=Krylov" \
    --set "Linear solver/Displacement preconditioner=geometric" \
    --set "Linear solver/Multigrid coarse size=300" "$@" > "${name}_GMG.log" 2>&1
  check $? "$name with the geometric multigrid finished ($(grep -m1 'reached\|error\|failed' "${name}_GMG.log"))"
  "$compare" --relative 1e-6 --newton 1 "${name}_MUMPS/statistics.csv" "${name}_GMG/statistics.csv" \
    > "${name}_compare.log"
  check $? "$name: geometric multigrid and MUMPS statistics agree ($(tail -1 "${name}_compare.log"))"
  local per_solve levels
  per_solve=$(grep -o "([0-9.e+-]* per solve)" "${name}_GMG.log" | tr -d '(' | awk '{print $1}')
  levels=$(grep -o "geometric multigrid, levels of [0-9, ]* unknowns" "${name}_GMG.log")
  [[ -n $levels ]]
  check $? "$name: the displacement block by the geometric multigrid (${levels:-not used})"
  awk -v p="${per_solve:-1e9}" -v m="$max" 'BEGIN { exit !(p <= m) }'
  check $? "$name: ${per_solve:-no} Krylov iterations per solve (at most $max)"
}
# fixed_steps_only DT STEPS: fixed_steps without the error control of the scene.
fixed_steps_only() {
  fixed_steps "$@"
  steps+=(--set "Time stepping/Tolerance=0")
}

grid=(--set "Background grid/Cells=40, 320" --set "Material points/Points per cell=3")
fixed_steps_only 1e-6 3
run undrained 20 constrained_swelling.prm "${steps[@]}" "${grid[@]}"
fixed_steps_only 1e-3 1
run cube 19 free_swelling_cube.prm "${steps[@]}" --set "Background grid/Cells=20, 20, 20"
finish
