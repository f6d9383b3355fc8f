# A run that cannot converge (a stiffer gel, N nu = 1e-4, whose scaled residuals stop on round-off
# at about 6e-13, against 'Newton/Tolerance = 1e-13', which --check accepts: every attempt halving
# down to 'Minimum step') says so on stderr, where a failed run's message is looked for, as well as
# in the log, names the entry to change, exits with status 1 and keeps complete files.
source "$(dirname "$0")/common.sh"
"$gelmpm" "$scene" --set "Material/N nu=1e-4" --set "Newton/Tolerance=1e-13" \
  --set "Time stepping/Minimum step=1e-5" >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $((status != 1)) "exit status $status, expected 1"
grep -q "the run cannot converge beyond t/tau_d = 0; results up to there are in results" stderr
check $? "stderr does not say that the run cannot converge"
grep -q "the run cannot converge beyond t/tau_d = 0" stdout
check $? "the log does not say that the run cannot converge"
grep -q "Newton stalls at scaled residuals of .* the round-off of this scene's residual, above 'Newton/Tolerance' = 1e-13: give 'Newton/Tolerance' at least" stderr
check $? "stderr does not name 'Newton/Tolerance' as the cause"
check_statistics
finish
