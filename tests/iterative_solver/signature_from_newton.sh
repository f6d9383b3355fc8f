# 'Stability/Signature from = last Newton factorisation' reads the inertia and the Schur
# eigenvalues from the LDL^T that Newton's last iteration made (the tangent at the iterate before
# the converged state) instead of factorising the converged tangent (doc/method.md, "Going
# through an instability"). Against 'converged tangent':
# - the column of tests/output/column_onset.cc (h = H/8, Newton's method as in the scene, the
#   drained criterion, bisection to 1e-3 tau_d, ended at the bracket): the same stability.csv but
#   for the eigenvalues (bracket, and the tangent's inertia at its ends), the same states and
#   inertia at every step, the Schur eigenvalue to 1e-3 of the run's largest; one factorisation
#   fewer per analysis, each signature from Newton's factorisation;
# - the same column bracketed by the signature of the whole tangent ('Onset criterion =
#   tangent', read from Newton's factorisation; bisected to 1e-2 tau_d): the same bracket and
#   inertia at its ends;
# - §4.1 to 0.1 tau_d with modified Newton (the default 'Reuse contraction'), where most steps
#   end on a kept factorisation: those analyses factorise the converged tangent (the log counts
#   both kinds), and the statistics agree to 1e-6; with 4 points per cell and direction instead
#   of the scene's 6 (the same 27 steps and five sparsity patterns, at two thirds of the CPU time).
source "$(dirname "${BASH_SOURCE[0]}")/../mpi/common.sh"
# run NAME SCENE SOURCE [--set ...]: the scene with 'Signature from = SOURCE' into NAME_SOURCE/.
run() {
  local name="$1" scene="$2" from="$3"
  shift 3
  run_with_mumps "${name}_${from}" "$scene" --set "Stability/Signature from=${from//_/ }" "$@"
}
# both NAME SCENE [--set ...]: the scene with either source; statistics compared.
both() {
  local name="$1" scene="$2"
  shift 2
  run "$name" "$scene" converged_tangent "$@"
  run "$name" "$scene" last_Newton_factorisation "$@"
}
# same_stability NAME: stability.csv identical but for the eigenvalue columns, and not empty.
same_stability() {
  local a="$1_converged_tangent/stability.csv" b="$1_last_Newton_factorisation/stability.csv"
  [[ $(wc -l < "$a") -ge 2 ]]
  check $? "$1: a loss of stability bracketed ($(tail -1 "$a"))"
  local columns
  columns=$(head -1 "$a" | tr ',' '\n' | grep -nv '^eig_' | cut -d: -f1 | paste -sd,)
  cmp -s <(cut -d, -f"$columns" "$a") <(cut -d, -f"$columns" "$b")
  check $? "$1: the same bracket and inertia from Newton's factorisation ($(tail -1 "$b"))"
}
# factorizations NAME_SOURCE: the factorisations of the run's summary.
factorizations() {
  grep -o '[0-9]* factorisations' "$1.log" | cut -d' ' -f1
}
# signatures NAME KIND: how many signatures the log counts from KIND ("Newton's last
# factorisation" or "the converged tangent").
signatures() {
  grep -o "[0-9]* \(signatures \)\?from $2" "$1_last_Newton_factorisation.log" | cut -d' ' -f1
}

column=(--set "Background grid/Cells=140, 80" --set "Material points/Points per cell=3"
        --set "Time stepping/Initial step=0.02" --set "Time stepping/Step caps=2: 0.02"
        --set "Time stepping/End time=0.3" --set "Time stepping/Stop at times="
        --set "Stability/Inertia=true" --set "Stability/Schur eigenvalues=1"
        --set "Newton/Initial chemical potential=grid" --set "Stability/Perturbation amplitude=0"
        --set "Stability/Signature step control=false" --set "Time stepping/Largest increment=0"
        --set "Time stepping/Displacement tolerance=0" --set "Newton/Initial displacement=zero"
        --set "Stability/End at onset=true")
column+=(--set "Stability/Bisection tolerance=1e-3")
both drained column_buckling.prm "${column[@]}"
"$compare" --relative 1e-10 --eigenvalues 1e-3 --newton 0 \
  drained_converged_tangent/statistics.csv drained_last_Newton_factorisation/statistics.csv \
  > drained_compare.log
check $? "drained: the same states and inertia, the eigenvalue to 1e-3 ($(tail -1 drained_compare.log))"
same_stability drained
reused=$(signatures drained "Newton's last factorisation")
fresh=$(factorizations drained_converged_tangent)
fewer=$(factorizations drained_last_Newton_factorisation)
[[ ${reused:-0} -gt 0 && $(signatures drained "the converged tangent") -eq 0 &&
   $((${fresh:-0} - ${fewer:-0})) -eq $reused ]]
check $? "drained: $reused signatures from Newton's factorisation, $fewer factorisations against $fresh"

# The tangent's signature counts the modes growing faster than 1/dt: bisected below 1e-2 tau_d the
# shorter retakes are stable and the bracket is abandoned (doc/method.md).
both tangent column_buckling.prm "${column[@]}" --set "Stability/Onset criterion=tangent" \
  --set "Stability/Bisection tolerance=1e-2"
same_stability tangent

both swelling constrained_swelling.prm --set "Material points/Points per cell=4" \
  --set "Time stepping/End time=0.1" \
  --set "Time stepping/Stop at times=0.1" --set "Stability/Inertia=true"
"$compare" --relative 1e-6 --newton 2 swelling_converged_tangent/statistics.csv \
  swelling_last_Newton_factorisation/statistics.csv > swelling_compare.log
check $? "swelling: the same inertia, statistics to 1e-6 ($(tail -1 swelling_compare.log))"
[[ $(signatures swelling "the converged tangent") -gt 0 ]]
check $? "swelling: steps ended on a kept factorisation factorise the converged tangent ($(grep -o '[0-9]* signatures.*tangent' swelling_last_Newton_factorisation.log))"

finish
