# A soft gel (N nu = 1e-3) whose exposed surface jumps from mu_0 to mu = 0 at t = 0: the layer the
# jump swells is thinner than a cell, its points distort more at every step, and after a few steps
# no step length converges (every attempt of the failing step starts from the same imbalance).
# The run used to stop with 'cannot converge' and no reason; it now names the failing step's
# reason, the jump (piece, mu_0, value) and the fix (a ramp from mu_0).
source "$(dirname "$0")/common.sh"
"$gelmpm" "$scene" --set "Material/N nu=1e-3" \
  --set "Boundary conditions/exposed/Chemical potential value/Function expression=0" \
  --set "Time stepping/End time=1" --set "Time stepping/Minimum step=1e-5" >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $((status != 1)) "exit status $status, expected 1"
grep -q "the run cannot converge beyond t/tau_d = .*: the step at t/tau_d = .* failed (" stderr
check $? "stderr does not give the failing step's reason"
grep -q "the chemical potential prescribed on 'exposed' jumps at t = 0 from the gel's mu_0/(k_BT) = -0.147892 to 0, and the run failed before solvent could diffuse across one cell" stderr
check $? "stderr does not name the jump"
grep -q "Ramp the prescribed value from mu_0" stderr
check $? "stderr does not give the fix"
[[ $(grep -c . stderr) -eq 1 ]]
check $? "stderr has more than one line"
check_statistics
finish
