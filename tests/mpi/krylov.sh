# The iterative solver (Linear solver/Solver = Krylov) on two MPI ranks against one: GMRES on
# distributed vectors, the distributed block preconditioner (ML on K_uu, the Schur approximation
# formed by Trilinos' sparse products and factorised by MUMPS; 'Schur complement = diagonal', the
# one approximation built distributed) and, on the column, the iterative
# drained criterion (LOBPCG on the distributed K_uu). Each scene runs on one rank and on two; the
# statistics must agree to 1e-6 of each column's largest value (each linear solve reduces its
# residual by 1e-8; Newton iterations within one), the drained eigenvalues to 1e-4 of their
# column's largest value (LOBPCG stops at a residual of 1e-8 ||K_uu||, so the ranks' round-off
# moves the converged values by up to about 1e-5 of the third eigenvalue), and the two-rank log
# must say that the displacement block was solved distributed:
# - §4.1 (prm/constrained_swelling.prm), 3 steps of 1e-4 tau_d, the algebraic multigrid;
# - the free-swelling cube (prm/free_swelling_cube.prm) on 14^3 cells, one step of 1e-3 tau_d
#   (as tests/iterative_solver/krylov_against_mumps; 20^3 cells took 3 times the CPU time);
# - the §4.3 column (prm/column_buckling.prm) on a grid of half its resolution, 2 steps to
#   0.00225 tau_d with 'Eigensolver = iterative' (on one rank with the geometric multigrid, on two
#   with the algebraic one; the 2 further steps to 0.004 took half the column's time).
source "$(dirname "$0")/common.sh"
fixed_steps() { # fixed_steps DT END: the entries for steps of DT up to END, in ${steps[@]}
  steps=(--set "Time stepping/Initial step=$1" --set "Time stepping/Growth factor=1"
         --set "Time stepping/Step caps=" --set "Time stepping/Stop at times="
         --set "Time stepping/Tolerance=0" --set "Time stepping/End time=$2")
}
# compare_ranks NAME SCENE [--set ...]: the scene on one and on two ranks, compared.
compare_ranks() {
  local name="$1" scene="$2"
  shift 2
  local common=(--set "Output/Write particles=false" --set "Linear solver/Solver=Krylov" "$@")
  "$gelmpm" "$source_dir/prm/$scene" --set "Output/Directory=${name}_one" "${common[@]}" \
    > "${name}_one.log" 2>&1
  check $? "$name on one rank finished ($(grep -m1 'reached\|error\|failed' "${name}_one.log"))"
  "$mpiexec" -n 2 --oversubscribe "$gelmpm" "$source_dir/prm/$scene" \
    --set "Output/Directory=${name}_two" "${common[@]}" > "${name}_two.log" 2>&1
  check $? "$name on two ranks finished ($(grep -m1 'reached\|error\|failed' "${name}_two.log"))"
  grep -q "Krylov iterations in .*displacement block by algebraic multigrid (several MPI ranks;" \
    "${name}_two.log"
  check $? "$name: two ranks solved by the distributed Krylov path"
  local drained="drained_eig_1,drained_eig_2,drained_eig_3"
  "$compare" --relative 1e-6 --newton 1 \
    --ignore "residual_u,residual_mu,solvent_imbalance,wall_time,$drained" \
    "${name}_one/statistics.csv" "${name}_two/statistics.csv" > "${name}_compare.log"
  check $? "$name: statistics on two ranks agree with one rank ($(tail -1 "${name}_compare.log"))"
  "$compare" --relative 1e-4 --newton 1 \
    "${name}_one/statistics.csv" "${name}_two/statistics.csv" > "${name}_drained.log"
  check $? "$name: to 1e-4 with the drained eigenvalues ($(tail -1 "${name}_drained.log"))"
}

fixed_steps 1e-4 3e-4
compare_ranks swelling constrained_swelling.prm "${steps[@]}" \
  --set "Linear solver/Displacement preconditioner=algebraic"
fixed_steps 1e-3 1e-3
compare_ranks cube free_swelling_cube.prm "${steps[@]}" --set "Background grid/Cells=14, 14, 14"
compare_ranks column column_buckling.prm --set "Time stepping/End time=0.00225" \
  --set "Background grid/Cells=176, 100" --set "Material points/Points per cell=3" \
  --set "Stability/Eigensolver=iterative" --set "Stability/Inertia=false" \
  --set "Stability/Schur eigenvalues=0" --set "Stability/Signature step control=false"
for run in column_one column_two; do
  columns=$(head -1 "$run/statistics.csv" | tr ',' '\n' | grep -c '^drained_eig_')
  values=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "drained_eig_1") c = i }
                    NR > 1 && c && $c != "" { n++ } END { print n + 0 }' "$run/statistics.csv")
  [[ $columns -eq 3 && $values -gt 0 ]]
  check $? "$run: the drained eigenvalues were computed ($columns columns, $values steps)"
done
finish
