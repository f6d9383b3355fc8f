# The cheaper factorisations of MUMPS's LDL^T solve the same Newton systems as the full-rank
# double-precision one, and leave the stability analysis's signature as it was:
# - 'Linear solver/Precision = single' (single-precision factors, each solve refined in double
#   precision to a relative residual of 1e-13): the same steps, Newton iterations within one and
#   the same physical statistics to 1e-6 of each column's largest value, on §4.1 to 0.1 tau_d
#   with the paper's step control (2D; 4 points per cell and direction instead of the scene's 6:
#   the same 27 steps and five sparsity patterns at two thirds of the CPU time) and on 2 steps of
#   the free-swelling cube at 14^3 cells (3D); on the column of tests/output/column_onset.cc
#   (h = H/8, the inertia of the full tangent at every step, one Schur eigenvalue, bisection to
#   1e-3 tau_d) the same bracket of the loss of stability and the same inertia at every step (the
#   stability analysis factorises in double precision: near the onset the single-precision
#   factors cannot be refined);
# - 'Linear solver/Compression = 1e-6' (block low-rank factors) on the same cube;
# - a tangent too ill-conditioned for single precision (§4.1 with both Nitsche penalties at their
#   bound of 1e8: its refinement stalls at a relative residual of about 2e-7) goes back to double
#   precision, says so, and gives the double-precision run's statistics (3 steps to 0.0002 tau_d,
#   2 sparsity patterns: the first factorisation falls back, the later ones stay in double
#   precision; it ran 10 steps to 0.002 before).
# The cube's run with the defaults (double precision, no compression) is the reference of both
# cube comparisons.
source "$(dirname "${BASH_SOURCE[0]}")/../mpi/common.sh"
# run_value NAME SCENE VALUE ENTRY [--set ...]: the scene with ENTRY = VALUE into NAME_VALUE/.
run_value() {
  local name="$1" scene="$2" value="$3" entry="$4"
  shift 4
  run_with_mumps "${name}_${value}" "$scene" --set "Linear solver/${entry}=${value}" "$@"
}
# agree NAME DIRECTORY_A DIRECTORY_B WHAT: their statistics agree.
agree() {
  "$compare" --relative 1e-6 --newton 1 "$2/statistics.csv" "$3/statistics.csv" > "$1_compare.log"
  check $? "$1: statistics with $4 agree ($(tail -1 "$1_compare.log"))"
}
# run NAME SCENE VALUE_A VALUE_B ENTRY [--set ...]: the scene with ENTRY = VALUE_A and VALUE_B.
run() {
  local name="$1" scene="$2" a="$3" b="$4" entry="$5"
  shift 5
  run_value "$name" "$scene" "$a" "$entry" "$@"
  run_value "$name" "$scene" "$b" "$entry" "$@"
  agree "$name" "${name}_${a}" "${name}_${b}" "$entry = $a and $b"
}

run swelling constrained_swelling.prm double single Precision \
  --set "Material points/Points per cell=4" --set "Time stepping/End time=0.1" \
  --set "Time stepping/Stop at times=0.1"
grep -q "single precision, [0-9]* refinement steps" swelling_single.log
check $? "swelling: the solver line reports single precision ($(grep -o 'single precision, [0-9]* refinement steps' swelling_single.log))"

fixed_steps 0.01 2
cube=("${steps[@]}" --set "Background grid/Cells=14, 14, 14" --set "Time stepping/Tolerance=0")
run cube free_swelling_cube.prm double single Precision "${cube[@]}"
run_value cube_compressed free_swelling_cube.prm 1e-6 Compression "${cube[@]}"
agree cube_compressed cube_double cube_compressed_1e-6 "Compression = 0 (the default) and 1e-6"

run column column_buckling.prm double single Precision \
  --set "Background grid/Cells=140, 80" --set "Material points/Points per cell=3" \
  --set "Time stepping/Initial step=0.02" --set "Time stepping/Step caps=2: 0.02" \
  --set "Time stepping/End time=0.25" --set "Time stepping/Stop at times=" \
  --set "Stability/Inertia=true" --set "Stability/Bisection tolerance=1e-3" \
  --set "Newton/Initial chemical potential=grid" --set "Stability/Perturbation amplitude=0" \
  --set "Stability/Signature step control=false" --set "Time stepping/Largest increment=0" \
  --set "Time stepping/Displacement tolerance=0" --set "Newton/Initial displacement=zero"
# The eigenvalues (about 6e-7 at the bracket) carry the Newton iterates' differences.
columns=$(head -1 column_double/stability.csv | tr ',' '\n' | grep -nv '^eig_' | cut -d: -f1 | paste -sd,)
cmp -s <(cut -d, -f"$columns" column_double/stability.csv) \
  <(cut -d, -f"$columns" column_single/stability.csv)
check $? "column: stability.csv's bracket and inertia identical with single precision ($(tail -1 column_single/stability.csv))"
[[ $(wc -l < column_single/stability.csv) -ge 2 ]]
check $? "column: a loss of stability bracketed"

run ill_conditioned constrained_swelling.prm double single Precision \
  --set "Time stepping/End time=0.0002" --set "Time stepping/Stop at times=0.0002" \
  --set "Nitsche/Displacement penalty=1e8" --set "Nitsche/Chemical potential penalty=1e8"
grep -q "double precision after the single-precision factorisation's refinement stopped" \
  ill_conditioned_single.log
check $? "ill-conditioned: back to double precision, and said ($(grep -o 'double precision after[^;]*' ill_conditioned_single.log | head -1))"

finish
