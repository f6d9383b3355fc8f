# Steps whose error estimate the points' integration noise sets ('Time stepping/Tolerance = 1e-3',
# no step caps, growth factor 2: from t = 34.8 tau_d 18 steps to 36 tau_d exceed it whatever their
# size and are accepted as noise). The log says so once, at the first such step, and counts such
# steps in the summary, instead of one line a step. (A tolerance that no step can meet, 1e-300,
# is refused: tests/input_errors/step_tolerance_below_newton.)
source "$(dirname "$0")/common.sh"
"$gelmpm" "$scene" --set "Time stepping/Tolerance=1e-3" --set "Time stepping/Step caps=" \
  --set "Time stepping/Growth factor=2" --set "Time stepping/End time=36" >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $status "exit status $status, expected 0"
said=$(grep -c "exceeds its tolerance .* times whatever the step" stdout)
counted=$(sed -n 's/^gelmpm: \([0-9]*\) step(s) accepted with an error estimate above its tolerance.*/\1/p' stdout)
echo "said $said times, counted ${counted:-no} steps"
check $((said != 1)) "the log says $said times that a step exceeds its tolerance, expected once"
check $((${counted:-0} < 2)) "the summary counts ${counted:-no} steps accepted above the tolerance"
finish
