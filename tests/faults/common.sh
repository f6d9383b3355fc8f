# Sourced by the fault tests: the arguments, a scratch directory and checks of the output files.
set -u
gelmpm="$1"
scene="$2"
source "$(dirname "${BASH_SOURCE[0]}")/../scratch.sh"

# Every row of results/statistics.csv has as many fields as the header and ends with a newline.
check_statistics() {
  local file=results/statistics.csv
  [[ -s $file ]] || { echo "FAIL: $file is missing or empty"; fail=1; return; }
  [[ $(tail -c 1 "$file" | od -An -c | tr -d ' ') == '\n' ]] ||
    { echo "FAIL: $file ends inside a row"; fail=1; }
  local widths
  widths=$(awk -F, '{print NF}' "$file" | sort -u | wc -l)
  [[ $widths -eq 1 ]] || { echo "FAIL: $file has rows of different widths"; fail=1; }
}

# Every .vtu that results/particles.pvd lists exists and is complete; no temporary file is left.
check_series() {
  local pvd=results/particles.pvd
  [[ -s $pvd ]] || { echo "FAIL: $pvd is missing"; fail=1; return; }
  grep -q '</VTKFile>' "$pvd" || { echo "FAIL: $pvd is torn"; fail=1; }
  for f in $(sed -n 's/.*file="\([^"]*\)".*/\1/p' "$pvd"); do
    [[ -f results/$f ]] || { echo "FAIL: $pvd lists the missing $f"; fail=1; continue; }
    tail -c 200 "results/$f" | grep -q '</VTKFile>' || { echo "FAIL: $f is torn"; fail=1; }
  done
  ! ls results/*.tmp >/dev/null 2>&1 || { echo "FAIL: temporary files left: $(ls results/*.tmp)"; fail=1; }
}

finish() {
  [[ $fail -eq 0 ]] && echo "PASS"
  exit $fail
}

# check_signal NAME STATUS: send signal NAME (TERM, INT) to a run once it has written a few rows;
# the run must end after the current step with exit STATUS, say so, and leave a last output that is
# the state of the last row of statistics.csv.
check_signal() {
  local name=$1 expected=$2
  "$gelmpm" "$scene" --set "Output/Write particles=true" --set "Output/Interval steps=3" \
    >stdout 2>stderr &
  local pid=$!
  for _ in $(seq 600); do
    [[ $(cat results/statistics.csv 2>/dev/null | wc -l) -ge 6 ]] && break
    sleep 0.1
  done
  kill -"$name" $pid
  wait $pid
  local status=$?
  echo "exit status: $status"; cat stderr
  check $((status != expected)) "exit status $status, expected $expected"
  grep -q "SIG$name received: stopped after step" stderr
  check $? "stderr does not say that SIG$name stopped the run"
  check_statistics
  check_series
  local last_row last_vtu
  last_row=$(tail -n 1 results/statistics.csv | cut -d, -f3)
  last_vtu=$(sed -n 's/.*timestep="\([^"]*\)".*/\1/p' results/particles.pvd | tail -n 1)
  awk -v a="$last_row" -v b="$last_vtu" 'BEGIN { exit !(a - b < 1e-9 * (1 + a) && b - a < 1e-9 * (1 + a)) }'
  check $? "the last .vtu (t = $last_vtu) is not the last row's state (t = $last_row)"
}
