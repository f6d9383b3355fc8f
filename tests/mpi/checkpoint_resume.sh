# Checkpoint and restart on two ranks: a run killed (SIGKILL to both ranks) at two moments and
# stopped once by SIGTERM, each time resumed with --resume on two ranks, and finished after a
# last resume on one rank (a checkpoint is not tied to its number of ranks), ends with the
# statistics of the uninterrupted run on two ranks (gelmpm-compare-statistics: 1e-10) and with
# as many material points.
source "$(dirname "$0")/common.sh"
scene="$source_dir/tests/simulator/free_swelling_scene.prm"
# 40 x 40 cells: steps long enough (about 0.1 s) for the kills to fall inside the run.
options=(--set "Time stepping/End time=12" --set "Output/Write particles=true"
         --set "Background grid/Cells=40, 40"
         --set "Output/Interval steps=5" --set "Output/Directory=results")

"$mpiexec" -n 2 --oversubscribe "$gelmpm" "$scene" "${options[@]}" \
  --set "Output/Directory=whole" >whole.log 2>&1
check $? "the uninterrupted run on two ranks failed: $(tail -3 whole.log)"

# run_until SIGNAL STEPS [ARGS...]: start the run on two ranks with a checkpoint after every
# step, wait until statistics.csv has STEPS more rows and a random part of a second more, and
# send SIGNAL to both ranks (the children of the launcher).
run_until() {
  local signal=$1 rows=$(($2 + $(cat results/statistics.csv 2>/dev/null | wc -l)))
  shift 2
  "$mpiexec" -n 2 --oversubscribe "$gelmpm" "$scene" "${options[@]}" \
    --set "Checkpoint/Interval steps=1" "$@" >>killed.log 2>&1 &
  local pid=$!
  for _ in $(seq 1200); do
    [[ $(cat results/statistics.csv 2>/dev/null | wc -l) -ge $rows ]] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.05
  done
  sleep "0.$((RANDOM % 2))"
  kill -0 $pid 2>/dev/null
  check $? "the run ended before SIG$signal: the test does not interrupt it"
  pkill -"$signal" -P $pid
  wait $pid 2>/dev/null
  echo "SIG$signal after $(($(wc -l <results/statistics.csv) - 1)) steps"
}
run_until KILL 10
run_until KILL 10 --resume
run_until TERM 6 --resume
"$gelmpm" "$scene" "${options[@]}" --set "Checkpoint/Interval steps=1" --resume >>killed.log 2>&1
check $? "the last resumed run (one rank) failed: $(tail -3 killed.log)"
[[ $(grep -c "resumed from the checkpoint at step" killed.log) -eq 3 ]]
check $? "the log does not say three times that the run resumed"

"$compare" whole/statistics.csv results/statistics.csv
check $? "statistics.csv differs from the uninterrupted run's"
finish
