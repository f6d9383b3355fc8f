# SIGTERM while one step keeps failing and halving: Newton is allowed one iteration against a
# tolerance below the round-off of a stiffer gel's residual (N nu = 1e-4: about 6e-13 against
# 1e-13), so every attempt fails, and with 'Minimum step = 1e-300' the step
# would halve about 990 times before the run gave up (exit 1, "cannot converge"). The signal
# is looked for before every attempt: the run ends within one attempt of it with exit 143, a
# complete last output of the last accepted state (the initial one) and far fewer attempts than
# the halving would take.
source "$(dirname "$0")/common.sh"
"$gelmpm" "$scene" --set "Output/Write particles=true" --set "Newton/Maximum iterations=1" \
  --set "Material/N nu=1e-4" --set "Newton/Tolerance=1e-13" \
  --set "Time stepping/Minimum step=1e-300" >stdout 2>stderr &
pid=$!
for _ in $(seq 600); do
  [[ $(grep -c "failed" stdout 2>/dev/null) -ge 3 ]] && break
  sleep 0.05
done
kill -TERM $pid
wait $pid
status=$?
attempts=$(grep -c "failed" stdout)
echo "exit status: $status after $attempts failed attempts"; cat stderr
check $((status != 143)) "exit status $status, expected 143"
grep -q "SIGTERM received: stopped after step 0" stderr
check $? "stderr does not say that SIGTERM stopped the run after step 0"
check $((attempts >= 900)) "$attempts failed attempts: the signal waited for the halving to end"
check_statistics
check_series
finish
