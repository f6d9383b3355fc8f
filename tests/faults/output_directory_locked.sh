# Two runs into one output directory: while a run is writing into results/, a second run (also
# --resume) into it is refused with one message naming the first run's process, exit status 2,
# and the first run's files untouched; --check, which writes nothing, is not refused. The lock
# dies with its run: after a kill -9, a new run into the directory goes through.
source "$(dirname "$0")/common.sh"
# The first run takes short steps without end (it is killed below), so that it outlasts the checks.
first=(--set "Checkpoint/Interval steps=2" --set "Time stepping/End time=1e9"
  --set "Time stepping/Step caps=1e9: 0.01")
"$gelmpm" "$scene" "${first[@]}" >first.log 2>&1 &
pid=$!
trap 'kill -KILL $pid 2>/dev/null; rm -rf "$work"' EXIT
for _ in $(seq 600); do
  [[ $(cat results/statistics.csv 2>/dev/null | wc -l) -ge 4 && -s results/checkpoint.bin ]] && break
  sleep 0.1
done

# second_run WHAT ARGS...: a run with ARGS into results/ must be refused, the first run's files kept.
second_run() {
  local what=$1
  shift
  "$gelmpm" "$scene" "$@" >stdout 2>stderr
  local status=$?
  echo "$what: exit status $status: $(cat stderr)"
  check $((status != 2)) "$what: exit status $status, expected 2"
  grep -qF "'Output/Directory' is 'results', the output directory of another GelMPM run (process $pid)" stderr
  check $? "$what: stderr does not name the run that holds the directory"
  [[ $(grep -c . stderr) -eq 1 ]]
  check $? "$what: expected exactly one error line"
  [[ -s results/statistics.csv && -s results/original.prm && -s results/parameters.prm ]]
  check $? "$what: the first run's files were removed: $(ls results)"
  grep -q "End time *= 1e9$" results/parameters.prm
  check $? "$what: the first run's parameters.prm was rewritten"
}
second_run "a second run" --set "Time stepping/End time=0.1"
second_run "a second run with --resume" "${first[@]}" --resume
"$gelmpm" "$scene" --check >stdout 2>stderr
check $? "--check while a run holds the directory failed: $(cat stderr)"

kill -0 $pid 2>/dev/null
check $? "the first run ended before it was killed: $(tail -3 first.log)"
kill -KILL $pid
wait $pid 2>/dev/null
"$gelmpm" "$scene" --set "Time stepping/End time=0.1" >stdout 2>stderr
status=$?
check $status "a run after the holder was killed: exit status $status: $(cat stderr)"
check_statistics
finish
