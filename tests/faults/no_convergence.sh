# A run that cannot converge (Newton allowed one iteration against a tolerance it cannot meet,
# every attempt halving down to 'Minimum step') says so on stderr, where a failed run's message is
# looked for, as well as in the log, exits with status 1 and keeps complete files.
source "$(dirname "$0")/common.sh"
"$gelmpm" "$scene" --set "Newton/Maximum iterations=1" --set "Newton/Tolerance=1e-30" \
  --set "Time stepping/Minimum step=1e-6" >stdout 2>stderr
status=$?
echo "exit status: $status"; cat stderr
check $((status != 1)) "exit status $status, expected 1"
grep -q "the run cannot converge beyond t/tau_d = 0; results up to there are in results" stderr
check $? "stderr does not say that the run cannot converge"
grep -q "the run cannot converge beyond t/tau_d = 0" stdout
check $? "the log does not say that the run cannot converge"
check_statistics
finish
