# SIGINT (Ctrl-C) in the middle of a run: the run ends after the current step with a complete last
# output, says so and exits with 130.
source "$(dirname "$0")/common.sh"
"$gelmpm" "$scene" --set "Output/Write particles=true" --set "Output/Interval steps=3" \
  >stdout 2>stderr &
pid=$!
for _ in $(seq 600); do
  [[ $(cat results/statistics.csv 2>/dev/null | wc -l) -ge 6 ]] && break
  sleep 0.1
done
kill -INT $pid
wait $pid
status=$?
echo "exit status: $status"; cat stderr
check $((status != 130)) "exit status $status, expected 130"
grep -q "SIGINT received: stopped after step" stderr
check $? "stderr does not say that SIGINT stopped the run"
check_statistics
check_series
# The last output is the state of the last row of statistics.csv.
last_row=$(tail -n 1 results/statistics.csv | cut -d, -f3)
last_vtu=$(sed -n 's/.*timestep="\([^"]*\)".*/\1/p' results/particles.pvd | tail -n 1)
awk -v a="$last_row" -v b="$last_vtu" 'BEGIN { exit !(a - b < 1e-9 * (1 + a) && b - a < 1e-9 * (1 + a)) }'
check $? "the last .vtu (t = $last_vtu) is not the last row's state (t = $last_row)"
finish
