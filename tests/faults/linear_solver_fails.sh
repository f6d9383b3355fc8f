# A linear solver that fails at every solve (GMRES allowed one iteration) is a failed Newton
# iteration: the step is cut down to 'Minimum step' and the run says it cannot converge, naming the
# linear solver. It used to cut the step until the first iterate's residual alone met Newton's
# tolerance and accept such steps without a single solve (zero Newton iterations, the gel
# unchanged, the steps shrinking: the run crawled).
source "$(dirname "$0")/common.sh"
"$gelmpm" "$scene" --set "Linear solver/Solver=Krylov" --set "Linear solver/Krylov iterations=1" \
  --set "Time stepping/End time=0.002" --set "Time stepping/Minimum step=1e-6" >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $((status != 1)) "exit status $status, expected 1"
grep -q "the run cannot converge beyond t/tau_d = 0; results up to there are in results: the step at t/tau_d = 0 failed (the iterative solver (GMRES) did not reduce the residual" stderr
check $? "stderr does not name the linear solver as the cause"
accepted=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "newton_iterations") c = i }
                    NR > 2 && $c == 0' results/statistics.csv | wc -l)
check $((accepted != 0)) "$accepted steps were accepted with no Newton iteration"
check_statistics
finish
