# The modified Newton iteration's rules for a fresh tangent ('Newton/Reuse contraction', 'Reuse
# step ratio', 'Maximum reuses') solve to the same states as Newton's method with MUMPS, and each
# rule refuses the kept factorisation where it should:
# - §4.1 to 0.1 tau_d (2D; the paper's step caps change the step at every step) with the default
#   contraction 1e-3, a step ratio of 1.1 and at most 2 solves per factorisation: the same steps
#   and physical statistics as Newton's method (Reuse contraction = 0) to 1e-6 of each column's
#   largest value (the Newton iterations differ by design), fewer factorisations than Newton
#   iterations, and the log counts fresh tangents on each of the three rules; with 4 points per
#   cell and direction instead of the scene's 6 (the same 27 steps and five sparsity patterns, at
#   two thirds of the CPU time);
# - the free-swelling cube at 10^3 cells (3D), steps of 0.01, 0.005 (landing on a stop time) and
#   0.01 tau_d, contraction 0.1 and a step ratio of 1.5: the same statistics, and the two steps
#   after the change of the step start with a fresh tangent (2 on the step ratio);
# - both again with single-precision factors, whose solves with a kept factorisation are refined
#   only to a tenth of the contraction: the same statistics.
source "$(dirname "${BASH_SOURCE[0]}")/../mpi/common.sh"
# run NAME SCENE [--set ...]: the scene into NAME/, its log NAME.log (tests/mpi/common.sh).
run() { run_with_mumps "$@"; }
# same A B: B's statistics are A's to 1e-6 (the Newton iterations may differ by up to 10).
same() {
  "$compare" --relative 1e-6 --newton 10 "$1/statistics.csv" "$2/statistics.csv" > "$2_compare.log"
  check $? "$2: statistics agree with $1 ($(tail -1 "$2_compare.log"))"
}
# fresh NAME RULE: how many fresh tangents the log of NAME counts on RULE.
fresh() {
  grep -o "[0-9]* on the $2" "$1.log" | cut -d' ' -f1
}
# counts NAME: Newton iterations and factorisations of the run's summary.
counts() {
  grep -o '[0-9]* Newton iterations, [0-9]* factorisations' "$1.log"
}

swelling=(--set "Material points/Points per cell=4" --set "Time stepping/End time=0.1"
          --set "Time stepping/Stop at times=0.1")
reuse_2d=(--set "Newton/Reuse contraction=1e-3" --set "Newton/Reuse step ratio=1.1"
          --set "Newton/Maximum reuses=2")
run newton_2d constrained_swelling.prm "${swelling[@]}" --set "Newton/Reuse contraction=0"
run reuse_2d constrained_swelling.prm "${swelling[@]}" "${reuse_2d[@]}"
same newton_2d reuse_2d
read -r iterations _ _ factorizations _ <<< "$(counts reuse_2d)"
[[ ${factorizations:-0} -gt 0 && $factorizations -lt ${iterations:-0} ]]
check $? "reuse_2d: fewer factorisations than Newton iterations ($(counts reuse_2d))"
for rule in contraction "step ratio" "reuse count"; do
  [[ $(fresh reuse_2d "$rule") -gt 0 ]]
  check $? "reuse_2d: fresh tangents on the $rule ($(fresh reuse_2d "$rule"))"
done
run single_2d constrained_swelling.prm "${swelling[@]}" "${reuse_2d[@]}" \
  --set "Linear solver/Precision=single"
same newton_2d single_2d

cube=(--set "Background grid/Cells=10, 10, 10" --set "Time stepping/Tolerance=0"
      --set "Time stepping/Initial step=0.01" --set "Time stepping/Growth factor=1"
      --set "Time stepping/Step caps=" --set "Time stepping/Stop at times=0.015"
      --set "Time stepping/End time=0.025")
reuse_3d=(--set "Newton/Reuse contraction=0.1" --set "Newton/Reuse step ratio=1.5")
run newton_3d free_swelling_cube.prm "${cube[@]}" --set "Newton/Reuse contraction=0"
run reuse_3d free_swelling_cube.prm "${cube[@]}" "${reuse_3d[@]}"
same newton_3d reuse_3d
[[ $(fresh reuse_3d "step ratio") -eq 2 ]]
check $? "reuse_3d: the steps after the change of the step start fresh ($(fresh reuse_3d "step ratio") on the step ratio, $(counts reuse_3d))"
run single_3d free_swelling_cube.prm "${cube[@]}" "${reuse_3d[@]}" \
  --set "Linear solver/Precision=single"
same newton_3d single_3d

finish
