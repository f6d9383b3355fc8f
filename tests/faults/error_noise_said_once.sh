# A step error tolerance below what the points' integration noise allows ('Time stepping/
# Tolerance = 1e-300', no step caps): every step exceeds it whatever its size and is accepted as
# noise. The log says so once, at the first such step, and counts such steps in the summary,
# instead of one line a step.
source "$(dirname "$0")/common.sh"
"$gelmpm" "$scene" --set "Time stepping/Tolerance=1e-300" --set "Time stepping/Step caps=" \
  --set "Time stepping/End time=0.002" >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $status "exit status $status, expected 0"
said=$(grep -c "exceeds its tolerance .* times whatever the step" stdout)
counted=$(sed -n 's/^gelmpm: \([0-9]*\) step(s) accepted with an error estimate above its tolerance.*/\1/p' stdout)
echo "said $said times, counted ${counted:-no} steps"
check $((said != 1)) "the log says $said times that a step exceeds its tolerance, expected once"
check $((${counted:-0} < 2)) "the summary counts ${counted:-no} steps accepted above the tolerance"
finish
